// Helpers for tests that run `granshock run` in-process: options for a scene file and an
// output directory, and summary.json as JSON.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "run_command.hpp"

namespace granshock::testing {

inline RunOptions run_options(const std::filesystem::path& scene, const std::filesystem::path& out,
                              std::vector<std::string> sets = {}) {
  RunOptions o;
  o.scene_file = scene;
  o.out_dir = out;
  o.overrides = std::move(sets);
  o.quiet = true;
  return o;
}

inline nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace granshock::testing

// `granshock tradeoff SCENE.toml` (docs/accuracy.md): runs the scene at a reference at the
// most accurate settings and at one cheaper setting per case (tradeoff_plan.hpp), through
// the study runner, and writes the trade table: every case's cost and its differences
// from the reference, each beside the noise of a second seed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/figure_switch.hpp"

namespace granshock {

struct TradeoffOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;       // empty: runs/tradeoff_<scene name>
  std::vector<std::string> overrides;  // --set: the scene's keys, in every case
  bool collect = false;                // the table from finished cases, run nothing
  bool dry_run = false;                // list the cases and their cost, write nothing
  bool quiet = false;
  // The cases' figures and pareto.png (figure_switch.hpp).
  bool figures = figures_by_default();
};

// Writes OUT/tradeoff.toml (the study), runs it as `granshock study` does (skips finished
// cases, resumes interrupted ones), then OUT/trade.{csv,json,md} and OUT/pareto.png.
// The exit code of the study (0: every case finished); throws UserError for bad input.
int tradeoff_command(const TradeoffOptions& options);

}  // namespace granshock

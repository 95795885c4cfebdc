#include "cases/study/case_files.hpp"

#include <exception>
#include <system_error>

#include "analysis/json_file.hpp"
#include "io/run_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

nlohmann::json read_summary(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir / "summary.json", ec)) return nullptr;
  JsonFile summary = read_json_file(dir / "summary.json", "summary");
  return summary.value.is_object() ? std::move(summary.value) : nlohmann::json();
}

nlohmann::json summary_value(const nlohmann::json& summary, const std::string& key) {
  if (!summary.is_object()) return nullptr;
  const auto it = summary.find(key);
  return it == summary.end() ? nlohmann::json() : *it;
}

std::string stored_scene(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir / "run.h5", ec)) return {};
  try {
    return RunFile::open_read_only(dir / "run.h5").scene_resolved();
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace granshock

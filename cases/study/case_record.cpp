#include "cases/study/case_record.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "analysis/json_file.hpp"
#include "cases/build_info/build_description.hpp"
#include "cases/study/case_files.hpp"
#include "core/cpu_model.hpp"
#include "core/shell_text.hpp"
#include "core/user_error.hpp"
#include "io/atomic_file.hpp"
#include "io/fields_record.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError(fmt::format("cannot read '{}' for the case record", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The study file as the user named it when relative (studies/x.toml); an absolute path
// is the machine's, so only its name is kept.
std::string study_file_as_given(const std::string& file) {
  const fs::path path(file);
  return path.is_absolute() ? path.filename().string() : file;
}

// The run's own text with its directory's path replaced by the case's name: a record is
// committed, and committed files carry no path of the machine they were made on (the
// analysis names the directory in its warnings: "/home/u/runs/x/soft-1000: not yet
// steady"). The absolute path first, then the path as given.
std::string without_run_path(std::string text, const fs::path& run_dir, const std::string& name) {
  std::error_code ec;
  const std::string absolute = fs::absolute(run_dir, ec).lexically_normal().string();
  for (const std::string& path : {absolute, run_dir.string()}) {
    if (path.empty() || path == name) continue;
    for (std::size_t at = text.find(path); at != std::string::npos;
         at = text.find(path, at + name.size()))
      text.replace(at, path.size(), name);
  }
  return text;
}

// The command that runs the case again (from the folder the study was run in).
std::string rerun_command(const CaseRecordOrigin& o) {
  return fmt::format("granshock study {} --case {}", shell_quote(study_file_as_given(o.study_file)),
                     o.case_index);
}

bool record_stands(const fs::path& record_dir, const std::string& summary_text,
                   const std::string& scene, const std::vector<std::string>& overrides) {
  std::error_code ec;
  for (const char* name : {"summary.json", "scene.toml", "fields.h5", "record.json"})
    if (!fs::is_regular_file(record_dir / name, ec)) return false;
  if (file_text(record_dir / "summary.json") != summary_text ||
      file_text(record_dir / "scene.toml") != scene)
    return false;
  const nlohmann::json origin = read_json_file(record_dir / "record.json", "record").value;
  return origin.is_object() && origin.contains("overrides") &&
         origin["overrides"] == nlohmann::json(overrides);
}

}  // namespace

void write_case_record(const fs::path& run_dir, const fs::path& record_dir,
                       const CaseRecordOrigin& origin) {
  const nlohmann::json summary = read_summary(run_dir);
  if (!summary.is_object() || summary.value("completed", false) != true ||
      !summary.contains(kFieldsSummaryKey))
    throw UserError(
        fmt::format("'{}' holds no finished, analysed run to record", run_dir.string()));
  const std::string scene = stored_scene(run_dir);
  if (scene.empty())
    throw UserError(fmt::format("cannot read the resolved scene of '{}' for its record",
                                (run_dir / "run.h5").string()));
  const std::string summary_text =
      without_run_path(file_text(run_dir / "summary.json"), run_dir, origin.case_name);
  // The same run analysed the same way again (--collect): the record stands. HDF5 files
  // are not written byte for byte alike, and a committed record should change only when
  // its numbers or its settings do.
  if (record_stands(record_dir, summary_text, scene, origin.overrides)) return;
  std::error_code ec;
  fs::create_directories(record_dir, ec);
  if (ec)
    throw UserError(fmt::format("cannot create the record directory '{}': {}", record_dir.string(),
                                ec.message()));
  write_fields_record(run_dir / "fields.h5", record_dir / "fields.h5");
  write_file_atomically(record_dir / "scene.toml", scene);
  nlohmann::ordered_json origin_json;
  origin_json["record"] = kCaseRecordVersion;
  origin_json["study"] = origin.study;
  origin_json["study_file"] = study_file_as_given(origin.study_file);
  origin_json["case"] = origin.case_name;
  origin_json["case_index"] = origin.case_index;
  origin_json["overrides"] = origin.overrides;
  origin_json["command"] = rerun_command(origin);
  const nlohmann::json build = summary.value("build", nlohmann::json::object());
  origin_json["run_commit"] = build.value("commit", std::string("unknown"));
  origin_json["recorded_by_commit"] = build_commit();
  origin_json["cpu_model"] = summary.value("cpu_model", cpu_model_name());
  origin_json["threads"] = summary.value("threads", 0);
  origin_json["wall_seconds"] = summary.value("wall_seconds", 0.0);
  origin_json["cpu_seconds"] = summary.value("cpu_seconds", 0.0);
  write_file_atomically(record_dir / "record.json", origin_json.dump(1) + "\n");
  write_file_atomically(record_dir / "summary.json", summary_text);
}

ReadRecord read_case_record(const fs::path& record_dir, const std::vector<std::string>& overrides) {
  ReadRecord r;
  nlohmann::json summary = read_summary(record_dir);
  std::error_code ec;
  if (!summary.is_object() || summary.value("completed", false) != true ||
      !summary.contains(kFieldsSummaryKey) || !fs::exists(record_dir / "fields.h5", ec))
    return r;
  const nlohmann::json origin = fs::exists(record_dir / "record.json", ec)
                                    ? read_json_file(record_dir / "record.json", "record").value
                                    : nlohmann::json();
  if (!origin.is_object() || !origin.contains("overrides") ||
      origin["overrides"] != nlohmann::json(overrides)) {
    r.refused = fmt::format(
        "its record in {} was made with other settings (record.json \"overrides\"), so it runs "
        "again and its record is replaced",
        record_dir.string());
    return r;
  }
  r.summary = std::move(summary);
  return r;
}

std::uintmax_t case_record_bytes(const fs::path& record_dir) {
  std::uintmax_t bytes = 0;
  std::error_code ec;
  for (const char* name : {"summary.json", "scene.toml", "fields.h5", "record.json"}) {
    const std::uintmax_t size = fs::file_size(record_dir / name, ec);
    if (!ec) bytes += size;
  }
  return bytes;
}

}  // namespace granshock

// Study files of `granshock study` (docs/study.md, "The study file"): a base scene and the
// `--set` overrides that make each case of a parameter study, read from TOML. Every key is
// checked: an unknown key, a missing or mistyped value, an empty axis end in one UserError
// line naming the study file and the key.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cases/study/axis_value.hpp"
#include "cases/study/safe_name.hpp"

namespace granshock {

// How the axes make cases: every combination (product), the k-th value of every axis
// together (list, also called zip), or each axis on its own around the base scene (sweep).
enum class StudyMode { product, list, sweep };
std::string to_string(StudyMode mode);

struct StudyAxis {
  std::string name;  // a column of the study table and the name of its figure
  std::vector<AxisValue> values;
};

// A [[case]] entry: a case named by the user with its own overrides.
struct ExplicitCase {
  std::string name;
  std::vector<std::string> overrides;
};

// [slurm]: what `--emit slurm` writes besides the array (docs/study.md, "Slurm").
struct SlurmSettings {
  int cpus_per_task = 4;
  std::vector<std::string> options;  // extra #SBATCH options, e.g. "--partition=short"
};

struct StudySpec {
  std::filesystem::path file;  // the study file
  std::string name;
  std::filesystem::path base;  // the base scene, relative paths taken from the study file's folder
  std::filesystem::path out;   // [study] out (relative to the working directory), or runs/<name>
  // [study] records (relative to the study file's folder), where each finished case's
  // compact record is written (docs/study.md, "Campaign records"); empty: <out>/records.
  std::filesystem::path records;
  std::vector<std::string> common;  // [study] set: overrides of every case, before its own
  // `granshock study --set`: overrides of every case given on the command line, after the
  // file's (already in `common`; kept apart so that a Slurm script passes them on).
  std::vector<std::string> command_line_set;
  // `granshock study --accuracy BUDGET [--accuracy-table FILE]`: each case's settings chosen
  // for the budget on its own scene (docs/study.md, "An error budget"); the table empty for
  // the shipped one.
  struct Accuracy {
    std::string budget;
    std::filesystem::path table;
  };
  std::optional<Accuracy> accuracy;
  StudyMode mode = StudyMode::product;
  std::vector<StudyAxis> axes;
  std::vector<ExplicitCase> cases;
  SlurmSettings slurm;
};

// The longest study file read (1 MiB, as scene files).
inline constexpr std::size_t kMaxStudyFileBytes = std::size_t(1) << 20;

// Reads and checks a study file; throws UserError("study file 'PATH': ...").
StudySpec load_study_file(const std::filesystem::path& path);
// The same from text; `path` names the file in messages and anchors a relative `base`.
StudySpec parse_study(const std::string& text, const std::filesystem::path& path);

}  // namespace granshock

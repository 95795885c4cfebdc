// A study made ready to run (docs/study.md, "Checks before anything runs"): every case's
// scene loaded from the base scene and its overrides and checked as `granshock run` checks
// it, so that a typo in the last case is found before the first one runs.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cases/study/case_directory.hpp"
#include "cases/study/study_cases.hpp"
#include "cases/study/study_file.hpp"
#include "core/scene.hpp"

namespace granshock {

struct PlannedCase {
  StudyCase spec;
  std::filesystem::path dir;  // <out>/<name>
  // Its record (cases/study/case_record.hpp): <records>/cases/<name>.
  std::filesystem::path record_dir;
  Scene scene;                        // resolved, named after the case
  std::string resolved;               // its TOML (what `run --dry-run` prints)
  std::vector<std::string> warnings;  // of the checks before a run
  // With an error budget (StudySpec::accuracy): the choice for this case, as
  // `granshock run --accuracy` records it (summary.json: accuracy_choice; its overrides
  // are at the end of spec.overrides), and what was chosen and why, one line each.
  nlohmann::json accuracy_choice;
  std::vector<std::string> accuracy_report;
};

struct StudyPlan {
  StudySpec spec;
  std::filesystem::path out;
  std::vector<PlannedCase> cases;
};

// Loads the base scene and every case; throws UserError naming the study file and the case
// for a scene the run would refuse (an unknown key, a value out of range, an unstable time
// step, field sampling without enough samples), and for two cases of the same scene.
// `out`: the study's directory (--out, else the study file's out).
StudyPlan plan_study(const StudySpec& spec, const std::filesystem::path& out);

// The state of a planned case: its run directory, else its record if that was made with
// the case's overrides (cases/study/case_directory.hpp).
CaseDirectory inspect_planned_case(const StudyPlan& plan, const PlannedCase& c);

// Where a study's records go: [study] records, else <out>/records.
std::filesystem::path records_root(const StudySpec& spec, const std::filesystem::path& out);

// The overrides `granshock run` gets for a case: scene.name, the study's [study] set, then
// the case's own.
std::vector<std::string> run_overrides(const StudySpec& study, const PlannedCase& c);

}  // namespace granshock

// What a case's run directory holds (docs/study.md, "Skip and resume"), decided from the
// files `granshock run` writes (docs/output_format.md, "The run directory"): a finished run
// has summary.json with "completed": true and the field analysis' keys; an unfinished one
// has its checkpoint to resume from.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cases/study/case_files.hpp"  // read_summary, summary_value, stored_scene

namespace granshock {

enum class CaseState {
  missing,       // no run yet (no directory, an empty one, or one that is not a run's)
  finished,      // completed, fields analysed: skipped
  needs_fields,  // completed, but the field analysis did not finish (summary without its keys)
  resumable,     // a run directory with checkpoint.h5 and run.h5, not completed
  restartable    // a run directory with nothing to resume (killed before its first checkpoint)
};

std::string to_string(CaseState state);

struct CaseDirectory {
  CaseState state = CaseState::missing;
  nlohmann::json summary;   // summary.json, or null
  long steps_done = 0;      // steps of the last summary (0 without one)
  double wall_seconds = 0;  // wall time of all legs so far (summary.json wall_seconds)
  // Finished by its record alone: the run directory is gone (or was never here), its
  // record (cases/study/case_record.hpp) holds the summary.
  bool from_record = false;
  std::string record_refused;  // why a record that is there was not used
};

CaseDirectory inspect_case_directory(const std::filesystem::path& dir);
// The same for a study's case run with `overrides`: a case with no run directory whose
// record is whole and of those overrides is finished, from its record (a run directory, even an
// unfinished one, comes first: it is what the user is working on).
CaseDirectory inspect_case_directory(const std::filesystem::path& dir,
                                     const std::filesystem::path& record_dir,
                                     const std::vector<std::string>& overrides);

}  // namespace granshock

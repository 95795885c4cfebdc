// A finished case's compact record (docs/study.md, "Campaign records"): what the study
// table, the trade table and the paper's figures need of it, kept apart from its run
// directory so that a campaign's results outlive the directories (a cleaned disk, a work
// tree laid anew) and can be committed. A record directory holds
//   summary.json  the run's, as its field analysis left it, its directory's path replaced
//                 by the case's name (written last: a record whose summary.json is there
//                 and says completed is whole)
//   scene.toml    the resolved scene (run.h5's /scene/resolved)
//   fields.h5     the reduced fields (io/fields_record.hpp), well under 1 MB
//   record.json   where it came from: study, case, overrides, the command to run it again,
//                 the commit and CPU model of the run
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace granshock {

// What record.json says of the case beside what its run wrote.
struct CaseRecordOrigin {
  std::string study;       // the study's name
  std::string study_file;  // as given on the command line
  std::string case_name;
  int case_index = 0;
  std::vector<std::string> overrides;  // every --set the run got, in order
};

// The version record.json names in "record".
inline constexpr const char* kCaseRecordVersion = "granshock case record 1";

// Writes the record of the finished run in `run_dir` to `record_dir` (created; files
// replaced one by one, summary.json last). Throws UserError naming what could not be read
// or written.
void write_case_record(const std::filesystem::path& run_dir,
                       const std::filesystem::path& record_dir, const CaseRecordOrigin& origin);

// A record read back for a case run with `overrides` (every --set, in order).
struct ReadRecord {
  nlohmann::json summary;  // null: no whole record, or one of other settings
  std::string refused;     // why a record that is there is not used ("" when none is there)
};

// The summary of a whole record (summary.json completed, with the field analysis' keys)
// made with exactly `overrides`: a record of a case that has since changed its settings
// under the same name is not the case's (ReadRecord::refused says so).
ReadRecord read_case_record(const std::filesystem::path& record_dir,
                            const std::vector<std::string>& overrides);

// Bytes of the record's files together.
std::uintmax_t case_record_bytes(const std::filesystem::path& record_dir);

}  // namespace granshock

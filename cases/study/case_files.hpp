// What a study reads of a case's run directory or record (docs/study.md, "Campaign
// records"): its summary.json and the resolved scene in its run.h5. Used by the case
// directory's inspection (case_directory.hpp) and by the records (case_record.hpp), kept
// apart so that neither includes the other.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace granshock {

// The summary key the field analysis always writes (docs/fields.md, "summary.json").
inline constexpr const char* kFieldsSummaryKey = "fields_bins";

// summary.json of `dir`, or null when it is missing or not a JSON object.
nlohmann::json read_summary(const std::filesystem::path& dir);

// summary[key], or null when it has none.
nlohmann::json summary_value(const nlohmann::json& summary, const std::string& key);

// The resolved scene stored in dir/run.h5, or "" when it cannot be read (no file, or a run
// that holds it open).
std::string stored_scene(const std::filesystem::path& dir);

}  // namespace granshock

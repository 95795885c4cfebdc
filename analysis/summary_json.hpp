// summary.json of a run directory is shared: `granshock run` writes the run's keys,
// `granshock fields` adds its own. Merging keeps every key already there.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace granshock {

// The JSON object in `path`, or an empty object when there is no such file. Throws
// UserError naming the file when it is not a regular file, cannot be read, or does not
// hold a JSON object: `granshock fields` reads it before it writes anything.
nlohmann::json read_summary_json(const std::filesystem::path& path);

// Reads `path` when it exists (read_summary_json), sets every key of `keys` (replacing
// keys of the same name) and writes the result atomically. Throws UserError naming the
// file when it cannot be parsed or written.
void merge_summary_json(const std::filesystem::path& path, const nlohmann::json& keys);

// Writes `base` with every key of `keys` set into `path`, atomically: the summary of a
// run that `granshock fields --out` writes elsewhere.
void write_summary_json(const std::filesystem::path& path, nlohmann::json base,
                        const nlohmann::json& keys);

}  // namespace granshock

// summary.json of a run directory is shared: `granshock run` writes the run's keys,
// `granshock fields` adds its own. Merging keeps every key already there.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace granshock {

// Reads `path` when it exists (it must hold a JSON object), sets every key of `keys`
// (replacing keys of the same name) and writes the result atomically. Throws UserError
// naming the file when it cannot be parsed or written.
void merge_summary_json(const std::filesystem::path& path, const nlohmann::json& keys);

}  // namespace granshock

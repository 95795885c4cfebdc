// Reading the JSON files granshock reads back (a run's summary.json, a trade-off's
// trade.json): a regular file of bounded size whose nesting is checked before it is parsed,
// so that a file made deep on purpose ends in one UserError line instead of a stack overflow
// in the parser, the copies or the indented dump (docs/output_format.md, "summary.json").
#pragma once

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace granshock {

// The deepest nesting read: granshock's own files are 3 or 4 levels deep.
inline constexpr int kMaxJsonDepth = 64;
// The longest JSON file read (64 MiB; a summary.json is a few KiB).
inline constexpr std::size_t kMaxJsonFileBytes = std::size_t(64) << 20;

// The deepest nesting of arrays and objects in `text`, counted in one pass that skips
// strings (and their escapes); text that is not JSON is counted the same way, so the value
// bounds what a parser reaches before it stops.
int json_nesting_depth(std::string_view text);

// Throws UserError("<where>: JSON nested deeper than 64 levels") when `text` is.
void check_json_depth(std::string_view text, const std::string& where);

struct JsonFile {
  nlohmann::json value;  // discarded (is_discarded()) when the text is not JSON
  std::string error;     // then the parser's message
};

// Reads and parses `path`, a `what` ("summary", "accuracy table") for messages. Throws
// UserError for a file that cannot be opened, is not a regular file (io/regular_file.hpp: a
// FIFO would block), is longer than kMaxJsonFileBytes or is nested too deeply; text that is
// not JSON is returned as a discarded value, for the caller to judge.
JsonFile read_json_file(const std::filesystem::path& path, const std::string& what = "JSON file");

}  // namespace granshock

// Reading the keys of one TOML table of a scene file with every value checked: a missing,
// mistyped or out-of-range value ends in a UserError of one line naming the key, the value
// and what is accepted (docs/scene_format.md). Lengths are a number in metres or "N d" /
// "N m". finish() refuses the keys the table holds that nobody asked for. Host code only:
// toml++ does not compile as CUDA (io/CMakeLists.txt).
#pragma once

#include <toml++/toml.h>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace granshock::scene_toml {

// A key or value as echoed in a message: one line, at most 80 characters and "...".
std::string clip(const std::string& text);
// Throws UserError("scene key 'KEY' = VALUE: WHAT"), key and value clipped.
[[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& what);
// A TOML value as a message shows it: strings quoted, "(a table)", "(an array)".
std::string show(const toml::node& n);

class TableReader {
 public:
  // `table` may be null (the table is absent: every key takes its default); `path` is the
  // table's dotted name ("" for the root); `d_m` is the length unit of "N d".
  TableReader(const toml::table* table, std::string path, double d_m);

  std::string key(const std::string& name) const;  // the dotted key of `name`
  bool has(const std::string& name);
  const toml::node* node(const std::string& name);

  double number(const std::string& name, std::optional<double> fallback = std::nullopt);
  double number_in(const std::string& name, double lo, double hi, bool lo_open, bool hi_open,
                   std::optional<double> fallback = std::nullopt);
  // A number in [lo, hi]; a refusal says why the range is what it is, when `why` is given.
  double number_within(const std::string& name, double lo, double hi,
                       std::optional<double> fallback = std::nullopt, const std::string& why = {});
  double positive(const std::string& name, std::optional<double> fallback = std::nullopt);
  long integer_at_least(const std::string& name, long lo, long fallback);
  bool boolean(const std::string& name, bool fallback);
  std::string string(const std::string& name, std::optional<std::string> fallback = std::nullopt);
  std::string choice(const std::string& name, const std::vector<std::string>& options,
                     const std::string& fallback);
  // A length: a number in metres, or a string "N d" (N times d_m) or "N m"; finite.
  double length(const std::string& name, std::optional<double> fallback = std::nullopt);
  double length_of(const toml::node& n, const std::string& key) const;
  double positive_length(const std::string& name, std::optional<double> fallback = std::nullopt);
  // A length in [lo, hi] metres.
  double length_within(const std::string& name, double lo, double hi,
                       std::optional<double> fallback = std::nullopt, const std::string& why = {});
  const toml::table* table(const std::string& name);

  // Refuses the first key of the table that was never asked for, listing those that were
  // and naming the nearest of them where it looks like a typo.
  void finish() const;

 private:
  // Refuses a required key that is absent: as a typo where the table has an unknown key a
  // few edits from it ("restitucion"), else as missing. `what`: "a number", ...
  [[noreturn]] void missing(const std::string& name, const std::string& what) const;
  const toml::table* table_;
  std::string path_;
  double d_m_;
  std::set<std::string> known_;
};

}  // namespace granshock::scene_toml

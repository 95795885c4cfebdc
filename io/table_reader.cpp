#include "io/table_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/nearest_name.hpp"
#include "core/quoted_input.hpp"
#include "core/user_error.hpp"

namespace granshock::scene_toml {

namespace {

// Keys and values echoed in messages are cut to this length: one line, however long the
// input (a --set value may be megabytes).
constexpr std::size_t kEchoLength = 80;

std::string fmt_bound(double b) {
  return std::isinf(b) ? (b > 0 ? "inf" : "-inf") : fmt::format("{}", b);
}

}  // namespace

std::string clip(const std::string& text) {
  // Cut and escaped (core/quoted_input.hpp): no control byte of a value reaches the terminal.
  return printable_line(text, kEchoLength);
}

void fail(const std::string& key, const std::string& value, const std::string& what) {
  throw UserError(fmt::format("scene key '{}' = {}: {}", clip(key), clip(value), what));
}

std::string show(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string())
    os << '"' << s->get() << '"';
  else if (n.is_table())
    os << "(a table)";
  else if (n.is_array())
    os << "(an array)";
  else
    n.visit([&](auto&& v) { os << v; });
  return os.str();
}

TableReader::TableReader(const toml::table* table, std::string path, double d_m)
    : table_(table), path_(std::move(path)), d_m_(d_m) {}

std::string TableReader::key(const std::string& name) const {
  return path_.empty() ? name : path_ + "." + name;
}

bool TableReader::has(const std::string& name) {
  known_.insert(name);
  return table_ && table_->contains(name);
}

const toml::node* TableReader::node(const std::string& name) {
  known_.insert(name);
  return table_ ? table_->get(name) : nullptr;
}

double TableReader::number(const std::string& name, std::optional<double> fallback) {
  const toml::node* n = node(name);
  if (!n) {
    if (!fallback) missing(name, "a number");
    return *fallback;
  }
  const auto v = n->value<double>();
  if (!v || n->is_boolean()) fail(key(name), show(*n), "must be a number");
  if (!std::isfinite(*v)) fail(key(name), show(*n), "must be finite");
  return *v;
}

double TableReader::number_in(const std::string& name, double lo, double hi, bool lo_open,
                              bool hi_open, std::optional<double> fallback) {
  const double v = number(name, fallback);
  const bool ok = (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  if (!ok)
    fail(key(name), fmt::format("{}", v),
         fmt::format("must be in {}{}, {}{}", lo_open ? "(" : "[", fmt_bound(lo), fmt_bound(hi),
                     hi_open ? ")" : "]"));
  return v;
}

double TableReader::number_within(const std::string& name, double lo, double hi,
                                  std::optional<double> fallback, const std::string& why) {
  const double v = number(name, fallback);
  if (!(v >= lo && v <= hi))
    fail(key(name), fmt::format("{}", v),
         fmt::format("must be in [{:g}, {:g}]{}{}", lo, hi, why.empty() ? "" : ": ", why));
  return v;
}

double TableReader::positive(const std::string& name, std::optional<double> fallback) {
  const double v = number(name, fallback);
  if (!(v > 0)) fail(key(name), fmt::format("{}", v), "must be > 0");
  return v;
}

long TableReader::integer_at_least(const std::string& name, long lo, long fallback) {
  const toml::node* n = node(name);
  if (!n) return fallback;
  const auto v = n->value<int64_t>();
  if (!n->is_integer() || !v) fail(key(name), show(*n), "must be an integer");
  if (*v < lo) fail(key(name), show(*n), fmt::format("must be >= {}", lo));
  return long(*v);
}

bool TableReader::boolean(const std::string& name, bool fallback) {
  const toml::node* n = node(name);
  if (!n) return fallback;
  if (!n->is_boolean()) fail(key(name), show(*n), "must be true or false");
  return *n->value<bool>();
}

std::string TableReader::string(const std::string& name, std::optional<std::string> fallback) {
  const toml::node* n = node(name);
  if (!n) {
    if (!fallback) missing(name, "a string");
    return *fallback;
  }
  if (!n->is_string()) fail(key(name), show(*n), "must be a string");
  return *n->value<std::string>();
}

std::string TableReader::choice(const std::string& name, const std::vector<std::string>& options,
                                const std::string& fallback) {
  const std::string v = string(name, fallback);
  for (const auto& o : options)
    if (o == v) return v;
  fail(key(name), '"' + v + '"', fmt::format("must be one of {}", fmt::join(options, ", ")));
}

double TableReader::length(const std::string& name, std::optional<double> fallback) {
  const toml::node* n = node(name);
  if (!n) {
    if (!fallback) missing(name, "a length");
    return *fallback;
  }
  return length_of(*n, key(name));
}

double TableReader::length_of(const toml::node& n, const std::string& k) const {
  std::optional<double> metres;
  if (auto v = n.value<double>(); v && !n.is_string() && !n.is_boolean()) metres = *v;
  if (n.is_string()) {
    std::istringstream in(*n.value<std::string>());
    double value = 0;
    std::string unit, rest;
    if (in >> value >> unit && !(in >> rest) && std::isfinite(value)) {
      if (unit == "d") metres = value * d_m_;
      if (unit == "m") metres = value;
    }
  }
  if (!metres) fail(k, show(n), "must be a length: a number in metres, or \"N d\" or \"N m\"");
  // nan, inf, or "1e300 d" past the largest double: no comparison with a limit holds.
  if (!std::isfinite(*metres)) fail(k, show(n), "must be a finite length");
  return *metres;
}

double TableReader::positive_length(const std::string& name, std::optional<double> fallback) {
  const double v = length(name, fallback);
  if (!(v > 0)) fail(key(name), fmt::format("{} m", v), "must be > 0");
  return v;
}

double TableReader::length_within(const std::string& name, double lo, double hi,
                                  std::optional<double> fallback, const std::string& why) {
  const double v = length(name, fallback);
  if (!(v >= lo && v <= hi))
    fail(key(name), fmt::format("{} m", v),
         fmt::format("must be in [{:g}, {:g}] m{}{}", lo, hi, why.empty() ? "" : ": ", why));
  return v;
}

const toml::table* TableReader::table(const std::string& name) {
  const toml::node* n = node(name);
  if (!n) return nullptr;
  if (!n->is_table()) fail(key(name), show(*n), "must be a table");
  return n->as_table();
}

void TableReader::missing(const std::string& name, const std::string& what) const {
  // A required key spelled wrong is named as the typo it is, not as a missing key.
  if (table_)
    for (const auto& [k, v] : *table_) {
      const std::string typed(k.str());
      if (!known_.count(typed) && looks_like_typo_of(typed, name))
        fail(key(typed), show(v),
             fmt::format("unknown key; did you mean '{}' (required here: {})?", name, what));
    }
  fail(key(name), "(missing)", "this key is required (" + what + ")");
}

void TableReader::finish() const {
  if (!table_) return;
  for (const auto& [k, v] : *table_) {
    const std::string name(k.str());
    if (known_.count(name)) continue;
    const std::string nearest =
        nearest_name(name, std::vector<std::string>(known_.begin(), known_.end()));
    fail(key(name), show(v),
         fmt::format("unknown key{} (accepted here: {})",
                     nearest.empty() ? "" : "; did you mean '" + nearest + "'?",
                     fmt::join(known_, ", ")));
  }
}

}  // namespace granshock::scene_toml

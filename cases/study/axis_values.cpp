#include "cases/study/axis_values.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "cases/study/safe_name.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {

// A value as TOML text; a table only as an element of an array (an inline table).
std::string value_text(const toml::node& value, const std::string& where, bool in_array);

std::string float_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest exact form
  std::string text(buffer, r.ptr);
  // TOML needs a '.' or an exponent to read a float back as a float.
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return text;
}

std::string quoted(const std::string& s) {
  std::ostringstream os;
  os << toml::value<std::string>(s);  // toml++ quotes and escapes
  return os.str();
}

// The value as a reader sees it: a string without quotes, a number in its shortest form.
std::string display_text(const toml::node& value, const std::string& where) {
  if (const auto* s = value.as_string()) return s->get();
  return toml_value_text(value, where);
}

void flatten(const toml::table& table, const std::string& prefix, std::vector<std::string>& out,
             const std::string& where) {
  for (const auto& [key, node] : table) {
    const std::string dotted =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const auto* inner = node.as_table())
      flatten(*inner, dotted, out, where);
    else
      out.push_back(dotted + "=" + toml_value_text(node, where + " key '" + dotted + "'"));
  }
}

std::string value_text(const toml::node& value, const std::string& where, bool in_array) {
  if (const auto* t = value.as_table(); t && in_array) {  // an element of [[species]], say
    std::string text = "{ ";
    bool first = true;
    for (const auto& [key, node] : *t) {
      text += (first ? "" : ", ") + quoted(std::string(key.str())) + " = " +
              value_text(node, where, true);
      first = false;
    }
    return text + " }";
  }
  if (const auto* s = value.as_string()) return quoted(s->get());
  if (const auto* i = value.as_integer()) return std::to_string(i->get());
  if (const auto* f = value.as_floating_point()) return float_text(f->get());
  if (const auto* b = value.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = value.as_array()) {
    std::string text = "[";
    for (std::size_t k = 0; k < a->size(); ++k)
      text += (k ? ", " : "") + value_text(*a->get(k), where, true);
    return text + "]";
  }
  throw UserError(
      fmt::format("{}: {} is not a value a scene key takes (a string, a number, a "
                  "boolean or an array of them)",
                  where, value.is_table() ? "a table" : "a date or time"));
}

}  // namespace

std::string toml_value_text(const toml::node& value, const std::string& where) {
  return value_text(value, where, false);
}

AxisValue shorthand_value(const std::string& axis, const std::string& key, const toml::node& value,
                          const std::string& where) {
  if (value.is_table())
    throw UserError(fmt::format(
        "{}: a table, but the axis names one key ('{}'); give plain values, or drop 'key' and "
        "give every value as a table of overrides with a label",
        where, key));
  AxisValue v;
  v.text = display_text(value, where);
  v.overrides.push_back(key + "=" + toml_value_text(value, where));
  if (value.is_number()) v.number = value.value<double>();
  v.label = safe_name(axis + "-" + v.text);
  return v;
}

AxisValue table_value(const toml::table& table, const std::string& where) {
  AxisValue v;
  const toml::node* label = table.get("label");
  if (!label || !label->is_string() || label->as_string()->get().empty())
    throw UserError(fmt::format(
        "{}: needs a label (label = \"...\", a short name for the case names) beside its "
        "overrides",
        where));
  v.label = safe_name(label->as_string()->get());
  if (v.label.empty())
    throw UserError(fmt::format("{}: label '{}' has no letter or digit to name a case", where,
                                label->as_string()->get()));
  v.text = label->as_string()->get();
  if (const toml::node* value = table.get("value")) {
    if (value->is_number())
      v.number = value->value<double>();
    else if (value->is_string())
      v.text = value->as_string()->get();
    else
      throw UserError(fmt::format(
          "{}: 'value' must be a number or a string (what the table and figures show)", where));
  }
  toml::table overrides = table;
  overrides.erase("label");
  overrides.erase("value");
  flatten(overrides, "", v.overrides, where);
  return v;
}

}  // namespace granshock

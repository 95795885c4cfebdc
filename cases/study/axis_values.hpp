// The values of a study axis (docs/study.md, "Axes"), from their TOML form to `--set`
// overrides: the shorthand (one scene key, plain values) and the full form (a table of
// overrides with a label). Host code with toml++ (cases/CMakeLists.txt).
#pragma once

#include <toml++/toml.h>

#include <string>

#include "cases/study/axis_value.hpp"

namespace granshock {

// A TOML value as `--set key=value` reads it back to the same value: strings quoted and
// escaped, floats in their shortest exact form, arrays inline. Throws UserError for a
// table, a date or a time, which no scene key takes.
std::string toml_value_text(const toml::node& value, const std::string& where);

// The shorthand: `key = "inflow.area_fraction"` with the plain value `value`: label
// "<axis>-<value>", one override.
AxisValue shorthand_value(const std::string& axis, const std::string& key, const toml::node& value,
                          const std::string& where);

// The full form: a table with `label`, an optional `value` (a number or a string for the
// table and figures; default: the label) and scene keys, nested tables flattened to dotted
// keys (`inflow.velocity = 1.0` or `inflow = { velocity = 1.0 }`).
AxisValue table_value(const toml::table& value, const std::string& where);

}  // namespace granshock

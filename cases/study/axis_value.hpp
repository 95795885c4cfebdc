// One value of a study's axis (docs/study.md, "The study file"): what the study file reads
// (study_file.hpp) and what the axis readers make of a TOML value (axis_values.hpp), kept
// apart so that neither includes the other.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace granshock {

// One value of an axis: the overrides it applies and how it is named and tabulated.
struct AxisValue {
  std::string label;                   // part of the case name, filesystem-safe
  std::vector<std::string> overrides;  // "key=value", as `granshock run --set` takes them
  std::optional<double> number;        // the value in the table and figures, when a number
  std::string text;                    // the value in the table otherwise
};

}  // namespace granshock

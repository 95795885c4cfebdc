// The names of a study, its axes and its cases (docs/study.md, "The study file"): what the
// study file checks (study_file.hpp) and the axis readers make (axis_values.hpp), kept
// apart so that neither includes the other.
#pragma once

#include <string>

namespace granshock {

// Whether `name` can name a study, an axis or a case: 1-64 of A-Z a-z 0-9 . _ -, not
// starting with '.' or '-' (the rule of scene.name, docs/scene_format.md).
bool is_safe_name(const std::string& name);
// `text` made safe for a name: every run of other characters becomes '-', and leading
// '.' and '-' are dropped.
std::string safe_name(const std::string& text);

}  // namespace granshock

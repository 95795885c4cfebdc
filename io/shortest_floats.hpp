// The resolved scene's numbers in their shortest exact form: toml++ writes a double with
// all 17 significant digits (friction = 0.29999999999999999); the shortest text that
// reads back as the same double (std::to_chars, C++17) is what the user wrote (0.3).
#pragma once

#include <string>

namespace granshock {

// `toml` with every float value rewritten in its shortest round-trip form (still a TOML
// float: "200.0", not "200"). Strings, keys and table headers are left as they are.
std::string with_shortest_floats(const std::string& toml);

// The shortest text that reads back as `value`, as a TOML float.
std::string shortest_float(double value);

}  // namespace granshock

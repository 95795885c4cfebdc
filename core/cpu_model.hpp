// The processor's model name, written beside every measured speed (summary.json
// "cpu_model", the benchmarks' headers): speeds are the machine's, not the program's.
#pragma once

#include <string>

namespace granshock {

// The first "model name" of /proc/cpuinfo, or "unknown" where it has none.
std::string cpu_model_name();

}  // namespace granshock

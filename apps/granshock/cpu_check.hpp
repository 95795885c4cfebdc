// A build for the CPU of its build machine (-march=native, the default: CMakeLists.txt
// GRANSHOCK_NATIVE) would die of an illegal instruction on an older CPU, e.g. another
// node of a cluster. The program checks first and refuses in one line (docs/study.md,
// "On a cluster"). This file is compiled for any CPU of its architecture (apps/granshock
// does not take the solver's -march).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace granshock {

// The names in `compiled` (ended by a null pointer) that `supported` denies, in order.
std::vector<std::string> missing_cpu_features(
    const char* const* compiled, const std::function<bool(const std::string&)>& supported);

// The refusal line for missing features, naming them and how to build for this CPU.
std::string cpu_refusal(const std::vector<std::string>& missing, const std::string& march);

// The refusal for this CPU and this build, or empty when it runs the build (or the check
// cannot ask the CPU: not x86, not GCC or Clang).
std::string check_this_cpu();

// Writes the refusal as the program's one error line and ends it with exit code 2, or
// returns. Safe before the C++ libraries have initialised: write(2) and _exit.
void exit_unless_this_cpu_runs_the_build();

}  // namespace granshock

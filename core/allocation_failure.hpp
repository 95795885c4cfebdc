// A Kokkos allocation that failed reads as a user error: the scene asked for more memory
// than the machine (or the GPU) has. Kokkos reports it as a std::runtime_error of several
// lines ("Kokkos failed to allocate memory for label "verlet_neighbours". ... Allocation of
// size 3.4 G failed, likely due to insufficient memory."), which granshock once ended as an
// internal error (exit 3).
#pragma once

#include <optional>
#include <string>

namespace granshock {

// The one line to say for such an exception's what(), or nothing for any other error.
std::optional<std::string> allocation_failure(const std::string& what);

}  // namespace granshock

// A solver whose kernels take the host or the device branches, whatever the build's own
// (kernels/device/backends.hpp; docs/cuda.md, "Branch points"), so that one test program
// can run both and compare them.
#pragma once

#include <cstddef>
#include <memory>

#include "core/solver.hpp"

namespace granshock::test {

enum class Paths { host, device };
const char* to_string(Paths p);

// The build's own solver where it takes these paths (Kokkos' default backend); else the
// other paths on a host backend: Serial where it takes them (a GPU build: host paths),
// else the default host backend built for them here (double precision, Hertz contacts
// only). One process.
std::unique_ptr<Solver> make_solver_on_paths(const SolverSetup& setup, std::size_t capacity,
                                             Paths paths);

// The paths of make_solver's default backend in this build.
Paths default_paths();

}  // namespace granshock::test

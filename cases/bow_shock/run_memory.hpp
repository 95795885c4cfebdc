// The memory a bow-shock run needs, estimated from its scene before anything is allocated,
// and the refusal of a scene that needs more than the machine has (docs/stability.md,
// "Limits"). Runs past it allocated for minutes and then died in Kokkos ("failed to
// allocate 167.1 G" at numerics.skin = 300 d). The estimate follows the solver's arrays
// (kernels/): per particle slot, per neighbour-list entry, per cell, per field-sum block,
// and the host copies a checkpoint and a snapshot make; tests/scene/test_run_memory.cpp
// compares it with the bytes Kokkos allocates.
#pragma once

#include <optional>
#include <string>

#include "core/available_memory.hpp"
#include "core/scene.hpp"

namespace granshock {

struct MemoryEstimate {
  double particles = 0;   // per-particle device arrays at the run's capacity, bytes
  double lists = 0;       // Verlet lists (and the build's buffers)
  double cells = 0;       // the cell grid
  double field_sums = 0;  // the bin sums of every block, and the sampling's buffers
  double host = 0;        // host copies: checkpoint state and field sums, snapshot
  // The final field analysis, while the solver is still held: a few copies of every
  // block's sums (docs/benchmarks.md, "Memory": the paper case holds 87 MB through the
  // time loop and peaks at 231 MB there, for 35 MB of sums).
  double analysis = 0;
  double device() const { return particles + lists + cells + field_sums; }
  double total() const { return device() + host + analysis; }
};

// `processes`: the run's MPI processes; each holds its share of the particles, lists and
// cells, and all the field sums. `threads`: the host threads that keep a private copy of
// a field-sum block (0 on a device).
MemoryEstimate estimate_run_memory(const Scene& scene, int processes, int threads);
// The same for this build's default backend and thread count.
MemoryEstimate estimate_run_memory(const Scene& scene, int processes = 1);

// Throws UserError naming the key that drives the estimate when the run needs more than
// `available` bytes.
void check_run_memory(const Scene& scene, const MemoryEstimate& estimate, double available);

}  // namespace granshock

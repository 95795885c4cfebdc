// checkpoint.h5: everything a run needs to continue bitwise where it stopped (the solver
// state plus the run loop's own counters), written atomically so that an interruption
// while writing leaves the previous checkpoint intact. Layout: docs/output_format.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "solver_state.hpp"

namespace granshock {

// The run loop's state beside the solver's.
struct CheckpointExtras {
  std::uint64_t rng_counter = 0;  // insertion RNG events done (counter-based RNG position)
  long inserted = 0;              // cumulative counters since the start of the run
  long deleted_outlet = 0;
  long deleted_inlet = 0;
  double insertion_carry = 0;      // fractional particles owed to the inflow
  double wall_seconds_so_far = 0;  // wall time spent by all earlier legs of the run
  std::vector<double> bin_sums;    // the field accumulators, opaque (may be empty)
  std::vector<long> bin_shape;     // their shape, opaque (may be empty)
  std::string scene_resolved;      // resume refuses to continue under a changed scene
};

// Writes path + ".tmp", closes and syncs it, then renames it over `path`. Throws
// UserError naming the path when the directory is not writable (no .tmp is left), and
// std::invalid_argument when a per-particle array of `state` does not divide into rows.
void write_checkpoint(const std::filesystem::path& path, const SolverState& state,
                      const CheckpointExtras& extras);

// Reads a checkpoint back exactly. Throws UserError naming the path when it is missing,
// unreadable or not a granshock checkpoint.
SolverState read_checkpoint(const std::filesystem::path& path, CheckpointExtras& extras);

}  // namespace granshock

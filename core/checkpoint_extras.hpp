// The run loop's state that a checkpoint stores beside the solver's (SolverState).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace granshock {

struct CheckpointExtras {
  std::uint64_t rng_counter = 0;  // insertion RNG events done (counter-based RNG position)
  long inserted = 0;              // cumulative counters since the start of the run
  long deleted_outlet = 0;
  long deleted_inlet = 0;
  double insertion_carry = 0;      // fractional particles owed to the inflow
  double wall_seconds_so_far = 0;  // wall time spent by all earlier legs of the run
  // CPU time (all threads and processes) of the earlier legs; -1 where a leg did not
  // record it (checkpoint format 3 may lack it: io/checkpoint_file.hpp).
  double cpu_seconds_so_far = -1;
  // The field accumulators: grid sums, profile sums and samples per block, concatenated;
  // bin_shape holds the three lengths (both empty for a run without field sums).
  std::vector<double> bin_sums;
  std::vector<long> bin_shape;
  std::string scene_resolved;  // resume refuses to continue under a changed scene
  // The --set overrides of every leg, in order (the run's own and those of each resume):
  // `--resume` applies them again, so that it continues the run as it was set up. Absent
  // where none were given (a checkpoint written outside a run), and in format-3 files
  // written before they were kept (io/checkpoint_file.hpp).
  std::optional<std::vector<std::string>> scene_overrides;
  // run.h5 as it was when the checkpoint was written (io/run_file.hpp, RunFileRecord): the
  // run's id, its snapshot frames and time-series rows. Absent (empty, -1) where none was
  // given (a checkpoint written outside a run), and in format-3 files written before run
  // ids (io/checkpoint_file.hpp).
  std::string run_id;
  long run_frames = -1;
  long run_rows = -1;
};

}  // namespace granshock

// The options of `granshock run` (docs/design.md, "The command-line contract"), as the
// command line gives them: what the command (run_command.hpp) and the run it drives
// (bow_shock_run.hpp) both read, kept apart so that neither includes the other.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/figure_switch.hpp"
#include "core/run_modes.hpp"
#include "core/scene.hpp"
#include "core/solver.hpp"

namespace granshock {

struct RunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;  // empty: runs/<scene name>
  std::vector<std::string> overrides;
  bool overwrite = false;
  bool resume = false;
  bool force = false;         // run past the stable time step
  long stop_after_steps = 0;  // > 0: checkpoint and stop after this many steps (batch jobs)
  // > 0: the time loop's slices (between progress and signal checks) of at most this many
  // steps, not about 0.25 s of wall time each: a call pattern that does not follow the
  // machine's speed, as instruction counts under valgrind need (docs/benchmarks.md).
  long slice_steps = 0;
  bool quiet = false;  // no progress lines
  // The figures at the end (--no-figures, GRANSHOCK_FIGURES: figure_switch.hpp).
  bool figures = figures_by_default();
  // Several processes: how slab boundaries move and which axis the slabs divide
  // (core/solver.hpp); how snapshots reach run.h5 (core/run_modes.hpp).
  SlabBalance balance = SlabBalance::equal;
  SlabAxis slabs = SlabAxis::y;
  SnapshotOutput snapshot_output = SnapshotOutput::automatic;
  // One process on the host's threads: whether the run moves between the threads and one
  // thread (core/run_modes.hpp, backend_switch.hpp).
  BackendSwitchMode backend_switch = BackendSwitchMode::automatic;
  // And how the threads share the particles (core/run_modes.hpp).
  ThreadShareMode thread_shares = ThreadShareMode::by_time;
  bool dry_run = false;  // check the scene and the directory, print the resolved scene
  std::string accuracy;  // an error budget ("2%"): settings from a measured table
  std::filesystem::path accuracy_table;  // that table; empty: default_accuracy_table()
  nlohmann::json accuracy_choice;        // what run_scene chose for `accuracy`; null without
};

// The run directory: --out, or runs/<scene name>.
inline std::filesystem::path run_directory_of(const RunOptions& o, const Scene& scene) {
  return o.out_dir.empty() ? std::filesystem::path("runs") / scene.name : o.out_dir;
}

}  // namespace granshock

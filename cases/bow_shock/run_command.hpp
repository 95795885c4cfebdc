// `granshock run SCENE.toml`: simulates a bow-shock scene and writes its run directory
// (docs/design.md, "The command-line contract"): run.h5 (+ run.xmf), checkpoint.h5 and
// summary.json.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <vector>

#include "analysis/figure_switch.hpp"
#include "cases/bow_shock/run_observables.hpp"  // NumericalFailure
#include "core/communicator.hpp"
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
  bool quiet = false;         // no progress lines
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
  bool dry_run = false;  // check the scene and the directory, print the resolved scene
  std::string accuracy;  // an error budget ("2%"): settings from a measured table
  std::filesystem::path accuracy_table;  // that table; empty: default_accuracy_table()
  nlohmann::json accuracy_choice;        // what run_scene chose for `accuracy`; null without
};

// What `granshock run --dry-run` checks: the scene, the limits and guards of a run and the
// output directory, without writing anything. Throws UserError where the run would be
// refused; returns the resolved scene (TOML), the directory and the warnings.
struct RunCheck {
  std::string resolved_scene;
  std::filesystem::path directory;
  std::vector<std::string> warnings;
  bool calibrates_inflow = false;  // inflow.mach_at = "inlet_bins"
  std::string time_step;           // dt against t_c and the guard's stable limit, one line
};
RunCheck check_run(const RunOptions& options);

// With --resume: the options with the --set overrides of the run's earlier legs (kept in
// its checkpoint) before those given now, said in a note on stderr when `speaks`; as given
// otherwise, or where the checkpoint keeps none.
RunOptions with_run_overrides(const RunOptions& options, bool speaks);

// The run directory: --out, or runs/<scene name>.
std::filesystem::path run_directory_of(const RunOptions& options, const Scene& scene);

// Returns the process exit code: 0 done (or stopped by --stop-after-steps), 130/143
// interrupted by SIGINT/SIGTERM after writing a checkpoint. Throws UserError for bad input.
// On several processes (`comm`, docs/parallel.md) every rank calls it alike; rank 0 writes
// and speaks.
int run_scene(const RunOptions& options, const Communicator& comm = SingleProcess::instance());

}  // namespace granshock

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
#include "cases/bow_shock/run_options.hpp"
#include "core/communicator.hpp"
#include "core/run_modes.hpp"
#include "core/scene.hpp"
#include "core/solver.hpp"

namespace granshock {

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

// Returns the process exit code: 0 done (or stopped by --stop-after-steps), 130/143
// interrupted by SIGINT/SIGTERM after writing a checkpoint. Throws UserError for bad input.
// On several processes (`comm`, docs/parallel.md) every rank calls it alike; rank 0 writes
// and speaks.
int run_scene(const RunOptions& options, const Communicator& comm = SingleProcess::instance());

}  // namespace granshock

// A scene ready to run (docs/design.md, "The bow-shock case"): the scene as loaded,
// checked (run_checks.hpp), its damping calibrated (contact.restitution_mode = "discrete",
// docs/contact_model.md) and its sigma calibrated (inflow.mach_at = "inlet_bins",
// docs/fields.md), then checked again, since the time-step guard depends on both. Made once,
// before anything is written, and not changed after: `--dry-run` prints it and the run
// runs it, so both see the same scene and the same warnings.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cases/accuracy/certified_step.hpp"
#include "cases/bow_shock/inlet_calibration.hpp"
#include "core/solver.hpp"
#include "io/scene_file.hpp"
#include "kernels/models/restitution_calibration.hpp"

namespace granshock {

struct PreparedScene {
  LoadedScene loaded;  // the calibrated scene; `resolved` carries the calibrated sigma
  std::vector<std::string> warnings;
  std::optional<RestitutionCalibration> restitution;  // restitution_mode = "discrete"
  std::optional<InletCalibration> inlet;              // mach_at = "inlet_bins", calibrated
  const Scene& scene() const { return loaded.scene; }
};

struct PrepareOptions {
  bool force = false;                      // --force: the guard's refusals become warnings
  int processes = 1;                       // the memory check is per process
  std::optional<CertifiedStep> certified;  // --accuracy's measured step (run_checks.hpp)
  // The inlet calibration runs the channel several times; --dry-run leaves sigma at its
  // first guess and says so.
  bool calibrate_inflow = true;
  // The calibrations' lines as they happen (none: silent); the warnings are returned.
  std::function<void(const std::string&)> say;
  // Called once the scene has passed its checks, before the calibrations' cost: the run
  // checks its directory there, so that a refused directory is said at once, and returns
  // the backend it starts on, where the inlet calibration's channel runs. None: Kokkos'
  // default execution space.
  std::function<Backend()> checked;
};

// Throws UserError, one line naming the key, for a scene that must not run.
PreparedScene prepare_scene(LoadedScene loaded, const PrepareOptions& options);

}  // namespace granshock

// --resume (docs/output_format.md, "Resuming"): the checkpoint is read and checked against
// the scene before anything changes, so that a refused resume leaves the run directory as
// it was; then the solver, the inflow and the samples take it. And what the earlier legs'
// summary.json said, which the new one keeps.
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/bow_shock/inflow.hpp"
#include "cases/bow_shock/run_extension.hpp"
#include "core/checkpoint_extras.hpp"
#include "core/solver.hpp"
#include "core/solver_state.hpp"
#include "io/scene_file.hpp"

namespace granshock {

struct ResumePoint {
  SolverState state;
  CheckpointExtras extras;
  RunExtension extension;  // what this leg changes of the checkpoint's time keys
};

// Every rank reads the whole checkpoint (docs/parallel.md: N ranks resume what M wrote)
// and checks it against `scene`, the run's prepared scene: throws UserError where the
// scene's keys differ in more than a resume may change, or where the checkpoint does not
// fit the run its own scene describes.
ResumePoint read_resume_point(const std::filesystem::path& dir, const LoadedScene& scene,
                              const InflowController& inflow);

// Hands the checkpoint to the solver, the inflow and the samples per block; the
// extension's new production window drops the earlier sums or takes the catch-up sample.
// `point.state` is moved into the solver.
void resume_from(ResumePoint& point, const std::filesystem::path& dir, Solver& solver,
                 InflowController& inflow, std::vector<long>& samples);

// What the earlier legs' summary.json said: its warnings and its rate (null where it said
// nothing, or cannot be read: the run's own state is in the checkpoint).
struct EarlierSummary {
  nlohmann::json warnings, rate;
};
EarlierSummary read_earlier_summary(const std::filesystem::path& dir);

}  // namespace granshock

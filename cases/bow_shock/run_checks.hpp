// Everything `granshock run` checks before it writes anything (and all that `--dry-run`
// checks): the time-step guard, the contact law's range, and the limits on step counts,
// outputs and particle numbers that keep a run's counters and memory in range
// (docs/scene_format.md, "Limits"). Each refusal is one UserError naming the scene key.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cases/accuracy/certified_step.hpp"
#include "core/scene.hpp"
#include "kernels/models/time_step_guard.hpp"

namespace granshock {

struct RunLimits {
  static constexpr double max_steps = 1e12;                 // time.duration / time.dt
  static constexpr double max_snapshots = 1e5;              // particle snapshots in run.h5
  static constexpr double max_series_rows = 1e7;            // time-series rows
  static constexpr double max_checkpoints = 1e5;            // checkpoints written
  static constexpr double max_particles = 1 << 28;          // int32 list offsets (~8 partners each)
  static constexpr double max_cells = 1 << 28;              // int32 cell indices
  static constexpr double max_particle_ids = 2147483647.0;  // int32 global ids
};

// Throws UserError for a scene that must not run; returns the warnings to print. `force`
// turns the refusals of the time-step guard and of the overlap range into warnings. The
// memory a run needs is checked for each of `processes` (run_memory.hpp). A `certified`
// step past the guard's t_c/10 is said to be so, with the measurement that certified it,
// instead of "results lose accuracy".
std::vector<std::string> check_scene_before_run(
    const Scene& scene, bool force, int processes = 1,
    const std::optional<CertifiedStep>& certified = std::nullopt);

// The time-step guard and the contact law's range at the fastest impact the scene can
// produce (Scene::fastest_impact_speed).
TimeStepAssessment assess_time_step(const Scene& scene);
OverlapAssessment assess_overlap(const Scene& scene);

// Particles a run inserts in all: the prefill plus the inflow over the whole duration.
double expected_insertions(const Scene& scene);

}  // namespace granshock

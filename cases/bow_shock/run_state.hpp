// The run loop's half of checkpoint.h5 (docs/output_format.md, "/run"): everything besides
// the solver's state that a run needs to continue bitwise where it stopped (the inflow's
// RNG events and counters, the field sums and samples so far), packed and restored here,
// and what the schedule says a checkpoint at a given step must hold (RunFit, checked by
// core/checkpoint_checks.hpp before a resume).
#pragma once

#include <string>
#include <vector>

#include "cases/bow_shock/inflow.hpp"
#include "cases/bow_shock/sampling_plan.hpp"
#include "core/checkpoint_checks.hpp"
#include "core/checkpoint_extras.hpp"
#include "core/scene.hpp"
#include "core/solver.hpp"

namespace granshock {

CheckpointExtras pack_run_state(const std::string& scene_resolved, const Solver& solver,
                                const InflowController& inflow, const std::vector<long>& samples,
                                double wall_seconds, double cpu_seconds);

// Restores the inflow, the solver's field sums and the samples per block.
void restore_run_state(const CheckpointExtras& extras, Solver& solver, InflowController& inflow,
                       std::vector<long>& samples);

RunFit run_fit(const Scene& scene, const InflowController& inflow, const SamplingPlan& sampling,
               long step);

}  // namespace granshock

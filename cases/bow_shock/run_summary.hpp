// summary.json of a bow-shock run (docs/output_format.md, "summary.json"): counts, times
// and speeds, the time step against the contact, the inflow's account, and the effective
// restitution every pair gets at the run's dt. The field analysis adds its own keys.
#pragma once

#include <nlohmann/json.hpp>

#include "cases/bow_shock/inflow.hpp"
#include "cases/bow_shock/inlet_calibration.hpp"
#include "core/scene.hpp"
#include "core/solver.hpp"

namespace granshock {

struct RunTimes {
  double wall_seconds = 0;    // all legs of the run (resumed runs)
  double cpu_seconds = -1;    // CPU time of all legs, threads and processes; -1: not known
  double leg_seconds = 0;     // this leg alone
  double particle_steps = 0;  // this leg's
};

// `calibration`: the inflow's sigma calibration (inflow.mach_at = "inlet_bins"), or null.
nlohmann::json run_summary(const Scene& scene, const Solver& solver, const InflowController& inflow,
                           const InletCalibration* calibration, bool completed,
                           const RunTimes& times);

// contact.restitution_mode = "discrete": every pair's calibrated damping, its phase-averaged
// e_eff against the continuous damping's, its spread over the phase of the first contact
// step and its residual at other impact speeds; null in continuous mode.
nlohmann::json restitution_calibration_summary(const Scene& scene);

// How sigma was calibrated: target, first guess, every iterate, the sigma chosen.
nlohmann::json calibration_summary(const InletCalibration& calibration);

// The inflow's account: requested, inserted, backlog, lost (docs/scene_format.md).
nlohmann::json inflow_summary(const InflowController& inflow);

// The price of the run's time step on the contact law: e_eff of every pair, measured with
// the same kernels at the run's dt, at the mean inflow speed and at the fastest impact
// speed the time-step guard assumes.
nlohmann::json effective_restitution_table(const Scene& scene);

}  // namespace granshock

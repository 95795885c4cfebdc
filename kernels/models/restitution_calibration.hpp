// Restitution exact at the chosen time step (docs/contact_model.md, "Restitution at the
// chosen time step"). The damping of the `hertz` and `hooke` laws is derived for the
// continuous equation of motion; velocity Verlet at a finite dt returns another restitution
// (0.509-0.514 instead of 0.5 at the paper's dt of about t_c/5), and which one depends on
// where the first contact step falls on the time grid (its phase). In `discrete` mode the
// damping beta of every pair is found at start-up by bisection so that a head-on collision,
// integrated exactly as the solver integrates it, returns the requested e on average over
// that phase.
//
// The collision is integrated in the pair's relative coordinate: the gap g between the
// surfaces and its rate u (> 0 separating) with the reduced mass m* (for the obstacle, the
// particle's mass), in the solver's order (kernels/solver/velocity_verlet.hpp): a half kick
// with the last force, a drift, the force from the law at the new gap and the half-step
// rate, a second half kick. For two particles this is the solver's own arithmetic up to
// rounding, because equal and opposite forces kick the relative velocity by F/m*.
#pragma once

#include <string>
#include <vector>

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "core/solver_setup.hpp"

namespace granshock {

// Phases of the first contact step averaged over: the overlap at the first force evaluation
// is phase x (impact speed) x dt, at the midpoints of kCalibrationPhases equal intervals.
inline constexpr int kCalibrationPhases = 32;
// The calibrated residual is also reported at these multiples of the calibration speed.
inline constexpr double kResidualSpeedFactors[] = {0.1, 0.3, 1.0, 3.0};

// e_eff of one head-on impact at `speed` (m/s) whose first contact step overlaps by
// phase x speed x dt (phase in (0, 1]), with the pair's beta as given.
double discrete_restitution(ContactModelKind model, const PairProperties& p,
                            const ContactOptions& o, double dt, double speed, double phase);
// The same averaged over kCalibrationPhases phases.
double phase_averaged_restitution(ContactModelKind model, const PairProperties& p,
                                  const ContactOptions& o, double dt, double speed);

struct PairCalibration {
  std::string pair;
  double restitution = 0;               // requested e
  double beta_continuous = 0;           // ln e / sqrt(ln^2 e + pi^2)
  double beta = 0;                      // calibrated
  double dt_over_tc = 0;                // at the calibration speed
  double e_eff_continuous = 0;          // phase-averaged e_eff with beta_continuous
  double e_eff = 0;                     // phase-averaged e_eff with the calibrated beta
  double phase_min = 0, phase_max = 0;  // e_eff over the phases, calibrated beta
  // Phase-averaged e_eff - e at kResidualSpeedFactors x the calibration speed.
  std::vector<double> speed_residuals;
};

struct RestitutionCalibration {
  double speed = 0;  // m/s
  double dt = 0;
  std::vector<PairCalibration> pairs;
};

// The most integration steps of the reduced integrator a calibration may take (every
// pair together), about 100 s on one core (docs/stability.md, "Limits"): each pair takes
// about kCalibrationImpacts collisions of t_c/dt steps, so a tiny dt (1e-12 s for a t_c
// of microseconds) would calibrate for hours.
inline constexpr double kMaxCalibrationSteps = 1e9;

// The integration steps calibrate_pair takes for `pairs` at this dt and speed, estimated
// from each pair's t_c before anything is integrated.
double calibration_steps(ContactModelKind model, const std::vector<PairProperties>& pairs,
                         const ContactOptions& o, double dt, double speed);
// Throws UserError when calibration_steps passes kMaxCalibrationSteps, naming the dt that
// would fit.
void check_calibration_cost(ContactModelKind model, const std::vector<PairProperties>& pairs,
                            const ContactOptions& o, double dt, double speed);

// Finds beta for one pair; throws UserError when no beta returns e at this dt (an
// integrator that cannot reach e, e.g. e near 0 at a coarse step), or when the
// calibration would pass kMaxCalibrationSteps.
PairCalibration calibrate_pair(ContactModelKind model, const PairProperties& p,
                               const ContactOptions& o, double dt, double speed);

// discrete mode: calibrates every pair of `setup` at setup.dt and
// contacts.calibration_speed_m_per_s and stores the betas in setup.contacts (continuous
// mode: clears them). Returns what it found, for the run's summary; calling it again on a
// calibrated setup calibrates from the requested e again and gives the same betas.
RestitutionCalibration apply_restitution_mode(SolverSetup& setup);

}  // namespace granshock

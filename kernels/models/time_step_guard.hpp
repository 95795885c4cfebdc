// The time-step guard and the range of the contact law (docs/contact_model.md, "Time
// step"): from every pair a scene can form, at the fastest impact it can produce, the
// collision time t_c, the stability limit of velocity Verlet and the peak overlap, each
// from the scene's contact law (kernels/models/).
#pragma once

#include <string>
#include <vector>

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "core/solver_setup.hpp"

namespace granshock {

double collision_time(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                      double impact_speed);
double peak_overlap(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                    double impact_speed);
// Largest velocity-Verlet step for the stiffest moment of an impact at speed v. The law
// linearised at its peak overlap has stiffness k (omega = sqrt(k / m*)) and damping ratio
// zeta. A step that resolves the contact in a single force evaluation, in the worst phase
// (overlap v dt at approach speed v), kicks the pair by dt (k v dt + 2 zeta omega m* v) / m*:
// it rebounds at ((omega dt)^2 + 2 zeta omega dt - 1) v, faster than it came (energy
// created), once omega dt > sqrt(2 + zeta^2) - zeta. That is the limit used here. The
// stability limit of a sustained damped oscillation, omega dt < 2 (sqrt(1 + zeta^2) - zeta)
// (Belytschko, Liu & Moran, Nonlinear Finite Elements, 2000, eq. 6.2.28), is about sqrt(2)
// larger and does not bound an impact: there a single collision already returned up to
// 2.9 times its impact speed (docs/contact_model.md, "Time step";
// tests/physics/test_time_step_limit.cpp). For Hertz the linearisation overestimates the
// kick (below the peak overlap the secant stiffness and the damping are smaller), so the
// limit is conservative. With friction the tangential spring acting on the rolling mass
// 2/7 m* is stiffer and sets the limit.
double stable_time_step(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                        double impact_speed, bool friction);

struct TimeStepAssessment {
  enum class Verdict { ok, warn, refuse };
  Verdict verdict = Verdict::ok;
  double dt = 0;
  double impact_speed = 0;
  std::string stiffest_pair;  // the pair with the shortest collision time
  double t_c = 0;             // its collision time at impact_speed
  double dt_stable = 0;       // smallest stable step over all pairs
  double safe_dt = 0;         // t_c / 50: a step that resolves a contact well
  double dt_over_tc() const { return dt / t_c; }
  std::string message;  // empty when ok
};

// Compares dt with every pair at the impact speed: warn past t_c/10, refuse past the
// stability limit.
TimeStepAssessment assess_time_step(const std::vector<PairProperties>& pairs,
                                    ContactModelKind model, const ContactOptions& options,
                                    double impact_speed, double dt, bool friction);
TimeStepAssessment assess_time_step(const SolverSetup& setup, double impact_speed);

// Whether the contact law stays in its range at the fastest impact: a warning past
// kOverlapWarn of the pair's smaller diameter, a refusal past kOverlapRefuse
// (contact_settings.hpp), where the particles would nearly pass through each other
// (docs/contact_model.md).
struct OverlapAssessment {
  TimeStepAssessment::Verdict verdict = TimeStepAssessment::Verdict::ok;
  std::string pair;           // the pair with the largest relative overlap
  double overlap_over_d = 0;  // its peak overlap / smaller diameter
  std::string message;        // empty when ok
};
OverlapAssessment assess_overlap(const std::vector<PairProperties>& pairs, ContactModelKind model,
                                 const ContactOptions& options, double impact_speed);
OverlapAssessment assess_overlap(const SolverSetup& setup, double impact_speed);

}  // namespace granshock

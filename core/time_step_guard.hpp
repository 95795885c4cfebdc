// Hertz collision time and the time-step guard (DESIGN.md section 2.1).
#pragma once

#include <string>
#include <vector>

#include "pair_properties.hpp"

namespace granshock {

// t_c = 2.87 (m*^2 / (R* Y*^2 v))^(1/5): duration of an elastic Hertz impact at
// relative normal speed v (Johnson, Contact Mechanics, 1985, eq. 11.24).
double hertz_collision_time(const PairProperties& p, double impact_speed);

// Largest stable velocity-Verlet step for the stiffest moment of an impact at speed v.
// The Hertz law linearised at the peak overlap delta_max = (15 m* v^2 / (16 Y* sqrt R*))^(2/5)
// has stiffness k = 2 Y* sqrt(R* delta_max) and damping ratio zeta = -sqrt(5/6) beta;
// central differences are stable for omega dt < 2 (sqrt(1 + zeta^2) - zeta)
// (Belytschko, Liu & Moran, Nonlinear Finite Elements, 2000, eq. 6.2.28).
// With friction the tangential spring (kt = 8 G* sqrt(R* dn), effective mass 2/7 m* for
// rolling spheres) is stiffer and sets the limit.
double stable_time_step(const PairProperties& p, double impact_speed, bool friction);

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

// Peak overlap of an elastic Hertz impact at relative normal speed v:
// delta_max = (15 m* v^2 / (16 Y* sqrt(R*)))^(2/5) (Johnson, Contact Mechanics, 1985,
// eq. 11.23). The Hertz law assumes overlaps small against the radii.
double hertz_peak_overlap(const PairProperties& p, double impact_speed);

// Whether the contact law stays in its range at the fastest impact: a warning past
// kOverlapWarn of the pair's smaller diameter, a refusal past kOverlapRefuse, where the
// particles would nearly pass through each other (docs/contact_model.md).
struct OverlapAssessment {
  TimeStepAssessment::Verdict verdict = TimeStepAssessment::Verdict::ok;
  std::string pair;           // the pair with the largest relative overlap
  double overlap_over_d = 0;  // its peak overlap / smaller diameter
  std::string message;        // empty when ok
};
inline constexpr double kOverlapWarn = 0.05;
inline constexpr double kOverlapRefuse = 0.2;
OverlapAssessment assess_overlap(const std::vector<PairProperties>& pairs, double impact_speed);

// Compares dt with every pair the scene can form at the fastest impact speed it can
// produce: warn past t_c/10, refuse past the stability limit.
TimeStepAssessment assess_time_step(const std::vector<PairProperties>& pairs, double impact_speed,
                                    double dt, bool friction);

}  // namespace granshock

#include "kernels/models/time_step_guard.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/models/models.hpp"

namespace granshock {

double collision_time(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                      double v) {
  return with_contact_model(model, [&](auto law) { return law.collision_time(p, o, v); });
}

double peak_overlap(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                    double v) {
  return with_contact_model(model, [&](auto law) { return law.peak_overlap(p, o, v); });
}

double stable_time_step(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                        double v, bool friction) {
  return with_contact_model(model, [&](auto law) {
    // omega dt <= sqrt(2 + zeta^2) - zeta: a contact resolved in one step gains no energy
    // (time_step_guard.hpp).
    // A calibrated beta > 0 (negative damping, restitution_calibration.hpp) is tiny; the
    // margin of an undamped law is kept for it.
    const double zeta = std::max(0.0, law.damping_ratio(p));
    const double margin = std::sqrt(2.0 + zeta * zeta) - zeta;
    double omega = std::sqrt(law.peak_normal_stiffness(p, o, v) / p.mass_star);
    if (friction)
      omega = std::max(
          omega, std::sqrt(law.peak_tangential_stiffness(p, o, v) / (2.0 / 7.0 * p.mass_star)));
    return margin / omega;
  });
}

TimeStepAssessment assess_time_step(const std::vector<PairProperties>& pairs,
                                    ContactModelKind model, const ContactOptions& options,
                                    double impact_speed, double dt, bool friction) {
  if (pairs.empty()) throw std::invalid_argument("assess_time_step: no contact pairs");
  if (!(impact_speed > 0))
    throw std::invalid_argument("assess_time_step: impact speed must be > 0");
  TimeStepAssessment a;
  a.dt = dt;
  a.impact_speed = impact_speed;
  a.t_c = INFINITY;
  a.dt_stable = INFINITY;
  for (const auto& p : pairs) {
    const double tc = collision_time(model, p, options, impact_speed);
    if (tc < a.t_c) {
      a.t_c = tc;
      a.stiffest_pair = p.name;
    }
    a.dt_stable =
        std::min(a.dt_stable, stable_time_step(model, p, options, impact_speed, friction));
  }
  a.safe_dt = a.t_c / 50.0;
  if (!(dt > 0)) {
    a.verdict = TimeStepAssessment::Verdict::refuse;
    a.message = fmt::format("time step dt = {:g} s must be positive", dt);
  } else if (dt > a.dt_stable) {
    a.verdict = TimeStepAssessment::Verdict::refuse;
    a.message = fmt::format(
        "time step dt = {:.3g} s is past the stable limit {:.3g} s for the {} contact at "
        "impact speed {:.3g} m/s (collision time t_c = {:.3g} s, dt/t_c = {:.3g}); use "
        "dt <= {:.3g} s (t_c/50), or --force to run anyway",
        dt, a.dt_stable, a.stiffest_pair, impact_speed, a.t_c, dt / a.t_c, a.safe_dt);
  } else if (dt > a.t_c / 10.0) {
    a.verdict = TimeStepAssessment::Verdict::warn;
    a.message = fmt::format(
        "time step dt = {:.3g} s resolves the {} contact (t_c = {:.3g} s at {:.3g} m/s) in "
        "only {:.1f} steps; results lose accuracy past t_c/10, t_c/50 = {:.3g} s is safe",
        dt, a.stiffest_pair, a.t_c, impact_speed, a.t_c / dt, a.safe_dt);
  }
  return a;
}

TimeStepAssessment assess_time_step(const SolverSetup& s, double impact_speed) {
  return assess_time_step(s.all_pairs(), s.contacts.model, s.contacts.options, impact_speed, s.dt,
                          s.contacts.has_friction());
}

OverlapAssessment assess_overlap(const std::vector<PairProperties>& pairs, ContactModelKind model,
                                 const ContactOptions& options, double impact_speed) {
  OverlapAssessment a;
  for (const auto& p : pairs) {
    const double ratio = peak_overlap(model, p, options, impact_speed) / p.min_diameter;
    if (ratio > a.overlap_over_d || a.pair.empty()) {
      a.overlap_over_d = ratio;
      a.pair = p.name;
    }
  }
  const std::string what = fmt::format(
      "the {} contact overlaps by {:.3g} of a diameter at impact speed {:.3g} m/s (peak "
      "overlap of the {} law)",
      a.pair, a.overlap_over_d, impact_speed, to_string(model));
  if (a.overlap_over_d > kOverlapRefuse) {
    a.verdict = TimeStepAssessment::Verdict::refuse;
    a.message = what + fmt::format(
                           ": past {} of a diameter the contact law has no meaning and particles "
                           "pass through each other; use stiffer materials or slower impacts, "
                           "or --force to run anyway",
                           kOverlapRefuse);
  } else if (a.overlap_over_d > kOverlapWarn) {
    a.verdict = TimeStepAssessment::Verdict::warn;
    a.message =
        what + fmt::format(": past {} of a diameter the contact law loses accuracy", kOverlapWarn);
  }
  return a;
}

OverlapAssessment assess_overlap(const SolverSetup& s, double impact_speed) {
  return assess_overlap(s.all_pairs(), s.contacts.model, s.contacts.options, impact_speed);
}

}  // namespace granshock

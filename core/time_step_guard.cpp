#include "time_step_guard.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace granshock {

double hertz_collision_time(const PairProperties& p, double v) {
  return 2.87 *
         std::pow(p.mass_star * p.mass_star / (p.radius_star * p.youngs_star * p.youngs_star * v),
                  0.2);
}

double hertz_peak_overlap(const PairProperties& p, double v) {
  return std::pow(15.0 * p.mass_star * v * v / (16.0 * p.youngs_star * std::sqrt(p.radius_star)),
                  0.4);
}

OverlapAssessment assess_overlap(const std::vector<PairProperties>& pairs, double impact_speed) {
  OverlapAssessment a;
  for (const auto& p : pairs) {
    const double ratio = hertz_peak_overlap(p, impact_speed) / p.min_diameter;
    if (ratio > a.overlap_over_d || a.pair.empty()) {
      a.overlap_over_d = ratio;
      a.pair = p.name;
    }
  }
  const std::string what = fmt::format(
      "the {} contact overlaps by {:.3g} of a diameter at impact speed {:.3g} m/s (Hertz peak "
      "overlap)",
      a.pair, a.overlap_over_d, impact_speed);
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
        what + fmt::format(": past {} of a diameter the Hertz law loses accuracy", kOverlapWarn);
  }
  return a;
}

double stable_time_step(const PairProperties& p, double v, bool friction) {
  const double sqrt_r = std::sqrt(p.radius_star);
  const double delta_max = hertz_peak_overlap(p, v);
  const double zeta = -std::sqrt(5.0 / 6.0) * p.beta;
  const double margin = 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta);
  const double kn = 2.0 * p.youngs_star * sqrt_r * std::sqrt(delta_max);
  double omega = std::sqrt(kn / p.mass_star);
  if (friction) {
    const double kt = 8.0 * p.shear_star * sqrt_r * std::sqrt(delta_max);
    omega = std::max(omega, std::sqrt(kt / (2.0 / 7.0 * p.mass_star)));
  }
  return margin / omega;
}

TimeStepAssessment assess_time_step(const std::vector<PairProperties>& pairs, double impact_speed,
                                    double dt, bool friction) {
  if (pairs.empty()) throw std::invalid_argument("assess_time_step: no contact pairs");
  if (!(impact_speed > 0))
    throw std::invalid_argument("assess_time_step: impact speed must be > 0");
  TimeStepAssessment a;
  a.dt = dt;
  a.impact_speed = impact_speed;
  a.t_c = INFINITY;
  a.dt_stable = INFINITY;
  for (const auto& p : pairs) {
    const double tc = hertz_collision_time(p, impact_speed);
    if (tc < a.t_c) {
      a.t_c = tc;
      a.stiffest_pair = p.name;
    }
    a.dt_stable = std::min(a.dt_stable, stable_time_step(p, impact_speed, friction));
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

}  // namespace granshock

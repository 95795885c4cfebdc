#include "kernels/models/restitution_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/user_error.hpp"
#include "kernels/models/clamped_normal.hpp"
#include "kernels/models/models.hpp"
#include "kernels/models/time_step_guard.hpp"
#include "kernels/solver/kick.hpp"

namespace granshock {

namespace {

// Bisection bounds on beta: -0.9999 is e of about 1e-30; beta > 0 is negative damping,
// which an integrator that loses energy may need to return e = 1.
constexpr double kBetaLow = -0.9999;
constexpr double kBetaHigh = 0.5;
constexpr int kBisections = 60;
// A sticking impact (e = 0 at the strongest damping) is followed this long (in t_c).
constexpr double kStickingContacts = 50;

template <class Model>
double one_impact(const PairProperties& p, const ContactOptions& o, double dt, double speed,
                  double phase) {
  const auto c = Model::template coefficients<double>(p, o);
  const double floor = normal_force_floor<double>(o);
  const double inv_m = 1.0 / p.mass_star, half = 0.5 * dt;
  // The drift that ends the first step overlaps by phase x speed x dt.
  double gap = (1.0 - phase) * speed * dt, rate = -speed, force = 0;
  bool touched = false;
  // A contact lasts about t_c; this bound only stops a pair that never parts.
  const double t_c = Model::collision_time(p, o, speed);
  const long max_steps = long(kStickingContacts * t_c / dt) + 100;
  for (long step = 0; step < max_steps; ++step) {
    half_kick(rate, half, force, inv_m, 0.0);
    gap += dt * rate;
    force = gap < 0 ? clamped_normal<Model>(c, -gap, rate, floor).force : 0.0;
    half_kick(rate, half, force, inv_m, 0.0);
    if (gap < 0) touched = true;
    if (touched && gap >= 0) return rate / speed;
  }
  // Still touching after 50 t_c: so much damping that the pair sticks (e = 0).
  return 0.0;
}

}  // namespace

double discrete_restitution(ContactModelKind model, const PairProperties& p,
                            const ContactOptions& o, double dt, double speed, double phase) {
  return with_contact_model(
      model, [&](auto law) { return one_impact<decltype(law)>(p, o, dt, speed, phase); });
}

namespace {

struct OverPhases {
  double mean = 0, min = INFINITY, max = -INFINITY;
};

OverPhases over_phases(ContactModelKind model, const PairProperties& p, const ContactOptions& o,
                       double dt, double speed) {
  OverPhases r;
  for (int k = 0; k < kCalibrationPhases; ++k) {
    const double e = discrete_restitution(model, p, o, dt, speed, (k + 0.5) / kCalibrationPhases);
    r.mean += e;
    r.min = std::min(r.min, e);
    r.max = std::max(r.max, e);
  }
  r.mean /= kCalibrationPhases;
  return r;
}

}  // namespace

double phase_averaged_restitution(ContactModelKind model, const PairProperties& p,
                                  const ContactOptions& o, double dt, double speed) {
  return over_phases(model, p, o, dt, speed).mean;
}

double calibration_steps(ContactModelKind model, const std::vector<PairProperties>& pairs,
                         const ContactOptions& o, double dt, double speed) {
  // Per phase: the continuous beta, both bounds, the bisections and the calibrated beta at
  // the calibration speed, each at most one contact long, except the strongest damping,
  // which may stick for kStickingContacts; then one impact per residual speed.
  const double contacts_at_speed = 3 + kBisections + kStickingContacts;
  double steps = 0;
  for (const PairProperties& p : pairs) {
    double contacts = contacts_at_speed * (collision_time(model, p, o, speed) / dt + 1);
    for (double f : kResidualSpeedFactors)
      contacts += collision_time(model, p, o, f * speed) / dt + 1;
    steps += kCalibrationPhases * contacts;
  }
  return steps;
}

void check_calibration_cost(ContactModelKind model, const std::vector<PairProperties>& pairs,
                            const ContactOptions& o, double dt, double speed) {
  const double steps = calibration_steps(model, pairs, o, dt, speed);
  if (steps <= kMaxCalibrationSteps) return;
  // Steps scale as 1/dt once t_c/dt is large.
  const double t_c = pairs.empty() ? 0 : collision_time(model, pairs.front(), o, speed);
  throw UserError(fmt::format(
      "restitution mode \"discrete\": calibrating the damping of {} pair{} at dt = {:.3g} s "
      "(t_c/dt = {:.3g} at {:g} m/s) would take about {:.3g} integration steps, more than the "
      "{:.0e} allowed; use dt >= {:.3g} s, or the continuous mode, which is exact as dt -> 0",
      pairs.size(), pairs.size() == 1 ? "" : "s", dt, t_c / dt, speed, steps, kMaxCalibrationSteps,
      dt * steps / kMaxCalibrationSteps));
}

PairCalibration calibrate_pair(ContactModelKind model, const PairProperties& requested,
                               const ContactOptions& o, double dt, double speed) {
  check_calibration_cost(model, {requested}, o, dt, speed);
  PairCalibration c;
  c.pair = requested.name;
  c.restitution = requested.restitution;
  c.beta_continuous = damping_beta(requested.restitution);
  c.dt_over_tc = dt / collision_time(model, requested, o, speed);
  PairProperties p = requested;
  const auto e_at = [&](double beta) {
    p.beta = beta;
    return phase_averaged_restitution(model, p, o, dt, speed);
  };
  c.e_eff_continuous = e_at(c.beta_continuous);
  double lo = kBetaLow, hi = kBetaHigh;
  const double e_lo = e_at(lo), e_hi = e_at(hi);
  if (!(e_lo <= c.restitution && c.restitution <= e_hi))
    throw UserError(fmt::format(
        "contact.restitution_mode = \"discrete\": no damping makes the {} pair return e = {:g} "
        "at dt = {:g} s (dt/t_c = {:.3g} at {:g} m/s): the phase-averaged restitution is "
        "{:.4g} with the strongest damping tried and {:.4g} with the weakest; use a smaller "
        "time step or the continuous mode",
        c.pair, c.restitution, dt, c.dt_over_tc, speed, e_lo, e_hi));
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (e_at(mid) < c.restitution ? lo : hi) = mid;
  }
  c.beta = 0.5 * (lo + hi);
  p.beta = c.beta;
  const OverPhases calibrated = over_phases(model, p, o, dt, speed);
  c.e_eff = calibrated.mean;
  c.phase_min = calibrated.min;
  c.phase_max = calibrated.max;
  for (double f : kResidualSpeedFactors)
    c.speed_residuals.push_back(phase_averaged_restitution(model, p, o, dt, f * speed) -
                                c.restitution);
  return c;
}

RestitutionCalibration apply_restitution_mode(SolverSetup& setup) {
  ContactSettings& contacts = setup.contacts;
  contacts.calibrated_beta.clear();
  contacts.obstacle_calibrated_beta.clear();
  RestitutionCalibration out;
  if (contacts.restitution_mode == RestitutionMode::continuous) return out;
  out.speed = contacts.calibration_speed_m_per_s;
  out.dt = setup.dt;
  if (!(out.speed > 0 && std::isfinite(out.speed)))
    throw UserError(fmt::format(
        "contact.restitution_mode = \"discrete\" needs a positive calibration speed (got {:g} "
        "m/s): set contact.calibration_speed",
        out.speed));
  check_calibration_cost(contacts.model, setup.all_pairs(), contacts.options, setup.dt, out.speed);
  const int n = int(setup.species.size());
  std::vector<std::vector<double>> beta(n, std::vector<double>(n, 0.0));
  std::vector<double> obstacle_beta(n, 0.0);
  const auto calibrate = [&](const PairProperties& p) {
    out.pairs.push_back(calibrate_pair(contacts.model, p, contacts.options, setup.dt, out.speed));
    return out.pairs.back().beta;
  };
  for (int a = 0; a < n; ++a) {
    for (int b = a; b < n; ++b) beta[a][b] = beta[b][a] = calibrate(setup.pair(a, b));
    // The obstacle's row serves a slab's walls too (core/solver_setup.hpp, wall_pair).
    if (setup.obstacle)
      obstacle_beta[a] = calibrate(setup.obstacle_pair(a));
    else if (setup.z_walls)
      obstacle_beta[a] = calibrate(setup.wall_pair(a));
  }
  contacts.calibrated_beta = beta;
  if (setup.obstacle || setup.z_walls) contacts.obstacle_calibrated_beta = obstacle_beta;
  return out;
}

}  // namespace granshock

#include "analysis/steadiness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/stagnation_line.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Moments {
  int n = 0;
  double mean = 0, squares = 0;  // sum of squared deviations from the mean
};

Moments moments(const std::vector<double>& x) {
  Moments m;
  m.n = static_cast<int>(x.size());
  if (x.empty()) return m;
  for (double v : x) m.mean += v;
  m.mean /= m.n;
  for (double v : x) m.squares += (v - m.mean) * (v - m.mean);
  return m;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
  char text[240];
  std::snprintf(text, sizeof text, pattern, a, b, c, d);
  return text;
}

}  // namespace

HalvesTrend halves_trend(const std::vector<double>& time, const std::vector<double>& values,
                         double t0, double t1, const SteadinessRule& rule) {
  HalvesTrend h;
  h.first_mean = h.second_mean = h.scatter = h.drift_over_scatter = h.relative_drift = kNaN;
  // Rows at the window's ends count (the series is written at fixed intervals and may
  // land on them); a tolerance of 1e-9 of the window keeps round-off from dropping them.
  const double slack = 1e-9 * std::max(t1 - t0, 0.0), middle = 0.5 * (t0 + t1);
  std::vector<double> first, second;
  for (std::size_t i = 0; i < time.size() && i < values.size(); ++i) {
    if (time[i] < t0 - slack || time[i] > t1 + slack || !std::isfinite(values[i])) continue;
    (time[i] < middle ? first : second).push_back(values[i]);
  }
  h.rows = static_cast<int>(first.size() + second.size());
  const int fewest = static_cast<int>(std::min(first.size(), second.size()));
  if (fewest < rule.min_rows_per_half) {
    h.reason = "only " + std::to_string(first.size()) + " and " + std::to_string(second.size()) +
               " time-series rows in the window's halves (a verdict needs " +
               std::to_string(rule.min_rows_per_half) + " in each)";
    return h;
  }
  const Moments a = moments(first), b = moments(second);
  h.determined = true;
  h.first_mean = a.mean;
  h.second_mean = b.mean;
  h.scatter = std::sqrt((a.squares + b.squares) / (a.n + b.n - 2));
  const double drift = b.mean - a.mean;
  const double mean = (a.mean * a.n + b.mean * b.n) / (a.n + b.n);
  h.relative_drift = mean != 0 ? drift / std::abs(mean) : kNaN;
  h.drift_over_scatter =
      h.scatter > 0 ? drift / h.scatter : (drift == 0 ? 0.0 : std::copysign(HUGE_VAL, drift));
  h.steady = std::abs(h.drift_over_scatter) <= rule.max_drift_over_scatter;
  return h;
}

FrontHalves front_halves(const DetachmentConvergence& convergence, double diameter,
                         const SteadinessRule& rule) {
  FrontHalves f;
  f.first_over_D = f.second_over_D = f.first_err = f.second_err = f.shift_over_error = kNaN;
  const Detachment *first = nullptr, *second = nullptr;
  for (const ConvergenceChoice& c : convergence.choices) {
    if (c.label == "first half of the window") first = &of(c.result, kPrimaryFront);
    if (c.label == "second half of the window") second = &of(c.result, kPrimaryFront);
  }
  if (first == nullptr || second == nullptr) {
    f.reason = "the window has fewer than 4 blocks, or no stagnation-line profile";
    return f;
  }
  if (!first->found || !second->found) {
    f.reason = std::string("no front in the ") + (!first->found ? "first" : "second") +
               " half of the window: " + (!first->found ? first->reason : second->reason);
    return f;
  }
  f.first_over_D = first->delta / diameter;
  f.second_over_D = second->delta / diameter;
  f.first_err = first->delta_err / diameter;
  f.second_err = second->delta_err / diameter;
  const double a = std::isfinite(f.first_err) ? f.first_err : 0,
               b = std::isfinite(f.second_err) ? f.second_err : 0;
  const double combined = std::sqrt(a * a + b * b);
  if (!(combined > 0)) {
    f.reason = "neither half's delta/D has an error (fewer than 2 blocks with a front in each)";
    return f;
  }
  f.determined = true;
  f.shift_over_error = std::abs(f.second_over_D - f.first_over_D) / combined;
  f.steady = f.shift_over_error <= rule.max_front_shift_over_error;
  return f;
}

Steadiness assess_steadiness(const RunSeries& s, double t0, double t1, const FieldPhysics& phys,
                             const DetachmentConvergence& convergence, const SteadinessRule& rule) {
  Steadiness st;
  st.window_start = t0;
  st.window_end = t1;
  const double length = phys.box_y_hi - phys.box_y_lo, u = phys.inflow_speed;
  st.flow_through_time = u > 0 ? length / u : kNaN;
  // The gas that met the obstacle's face at t = 0 (the prefill, before any shock stood
  // there) leaves through the outlet after (L - (y_c - R)) / U; without an obstacle the
  // whole channel's gas is replaced after L / U.
  const double disturbed = phys.obstacle ? phys.box_y_hi - phys.obstacle->face : length;
  st.washout_time = u > 0 ? std::min(disturbed, length) / u : kNaN;
  st.start_after_washout = !(t0 < st.washout_time * (1 - 1e-9));
  st.particles = halves_trend(s.time, s.particles, t0, t1, rule);
  st.kinetic_energy = halves_trend(s.time, s.kinetic_energy, t0, t1, rule);
  if (phys.obstacle)
    st.front = front_halves(convergence, phys.obstacle->width, rule);
  else
    st.front.reason = "the scene has no obstacle";

  std::vector<std::string> failed;
  if (!st.start_after_washout)
    failed.push_back(
        format("the window starts at %.3g s, before the gas that met the obstacle "
               "at t = 0 has left the domain (%.3g s; L/U = %.3g s)",
               t0, st.washout_time, st.flow_through_time));
  for (const auto& [what, trend] :
       {std::pair<const char*, const HalvesTrend*>{"the particle count", &st.particles},
        {"the kinetic energy", &st.kinetic_energy}})
    if (!trend->steady)
      failed.push_back(std::string(what) +
                       format(" drifts by %+.2g %% between the window's halves (%.2g times its "
                              "scatter)",
                              100 * trend->relative_drift, std::abs(trend->drift_over_scatter)));
  if (!st.front.steady)
    failed.push_back(
        format("delta/D moves from %.3g to %.3g between the window's halves (%.2g "
               "combined errors)",
               st.front.first_over_D, st.front.second_over_D, st.front.shift_over_error));
  st.steady = failed.empty();
  if (!st.steady) {
    st.warning = "not yet steady: ";
    for (std::size_t i = 0; i < failed.size(); ++i) st.warning += (i ? "; " : "") + failed[i];
    st.warning += "; its numbers describe a transient (docs/fields.md, section 12)";
  }
  return st;
}

}  // namespace granshock

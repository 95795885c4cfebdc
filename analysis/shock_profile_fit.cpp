#include "analysis/shock_profile_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace granshock {

namespace {
// log cosh x without overflow: |x| + log(1 + exp(-2|x|)) - log 2.
double log_cosh(double x) {
  const double a = std::abs(x);
  return a + std::log1p(std::exp(-2 * a)) - M_LN2;
}

// The bin average of (1 + tanh((y - y_s) / w)) / 2 over [a, b] and its derivatives by y_s
// and by ln w.
struct Step {
  double g, dg_dys, dg_dlnw;
};
Step step_average(double y_s, double w, double a, double b) {
  const double h = b - a, ua = (a - y_s) / w, ub = (b - y_s) / w;
  const double ta = std::tanh(ua), tb = std::tanh(ub);
  const double la = log_cosh(ua), lb = log_cosh(ub);
  Step s;
  s.g = 0.5 + 0.5 * w / h * (lb - la);
  s.dg_dys = 0.5 * (ta - tb) / h;
  s.dg_dlnw = 0.5 * w / h * (lb - la - ub * tb + ua * ta);
  return s;
}

// The top of the profile: the bins that stay within a tenth of the rise below its peak.
constexpr double kTop = 0.9;

struct Bin {
  double a, b, value;
};

double sum_of_squares(const std::vector<Bin>& bins, const ShockProfile& p) {
  double chi2 = 0;
  for (const Bin& bin : bins) {
    const double r = bin.value - bin_average(p, bin.a, bin.b);
    chi2 += r * r;
  }
  return chi2;
}

std::string in_mm(double y) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g mm", y * 1e3);
  return text;
}
}  // namespace

double bin_average(const ShockProfile& p, double y_lo, double y_hi) {
  return p.low + (p.high - p.low) * step_average(p.y_s, p.w, y_lo, y_hi).g;
}

double profile_at(const ShockProfile& p, double y) {
  return p.low + (p.high - p.low) * 0.5 * (1 + std::tanh((y - p.y_s) / p.w));
}

ShockProfileFit fit_shock_profile(const std::vector<double>& values, const std::vector<double>& y,
                                  double dy, int begin, int end, double min_jump_ratio,
                                  double window) {
  ShockProfileFit fit;
  begin = std::max(begin, 0);
  end = std::min({end, static_cast<int>(values.size()), static_cast<int>(y.size())});
  // The cut: the end of the profile's top, the largest value before the face and the bins
  // after it that stay within a tenth of the rise below it. Downstream the profile falls
  // again (T in the cooled, compacted cap at the wall), which a single step cannot describe;
  // a top of one bin alone lets a step far taller than the data fit the rise's foot.
  int peak = -1;
  double lowest = HUGE_VAL;
  for (int k = begin; k < end; ++k)
    if (std::isfinite(values[k])) {
      if (peak < 0 || values[k] > values[peak]) peak = k;
      lowest = std::min(lowest, values[k]);
    }
  int last = peak;
  while (peak >= 0 && last + 1 < end && std::isfinite(values[last + 1]) &&
         values[last + 1] >= lowest + kTop * (values[peak] - lowest))
    ++last;
  const double window_begin = peak >= 0 ? y[last] + 0.5 * dy - window : 0;
  std::vector<Bin> bins;
  for (int k = begin; k <= last; ++k)
    if (y[k] >= window_begin && std::isfinite(values[k]))
      bins.push_back({y[k] - 0.5 * dy, y[k] + 0.5 * dy, values[k]});
  fit.points = static_cast<int>(bins.size());
  if (bins.size() < 5) {
    fit.why = "the fit up to the profile's top holds " + std::to_string(bins.size()) +
              " bins; four parameters need 5";
    return fit;
  }
  fit.y_end = bins.back().b;
  const double y_begin = bins.front().a, span = fit.y_end - y_begin;

  // Start: the peak's level behind the front, the mean ahead of the first bin half-way up,
  // y_s at that bin's upstream edge, w one bin.
  ShockProfile p;
  p.high = values[peak];
  std::size_t first_up = 0;
  while (bins[first_up].value < 0.5 * (lowest + p.high)) ++first_up;
  p.low = 0;
  for (std::size_t i = 0; i < first_up; ++i) p.low += bins[i].value / first_up;
  if (first_up == 0) p.low = lowest;
  p.y_s = bins[first_up].a;
  p.w = dy;

  const double high_bound = lowest + 2 * (values[peak] - lowest);
  // Levenberg-Marquardt on (y_s, ln w, low, high), Marquardt's scaling of the diagonal,
  // each step projected into the box below.
  double chi2 = sum_of_squares(bins, p), lambda = 1e-3;
  bool converged = false;
  for (int iteration = 0; iteration < 500 && !converged; ++iteration) {
    Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
    Eigen::Vector4d jtr = Eigen::Vector4d::Zero();
    for (const Bin& bin : bins) {
      const Step s = step_average(p.y_s, p.w, bin.a, bin.b);
      const double jump = p.high - p.low;
      const Eigen::Vector4d row(jump * s.dg_dys, jump * s.dg_dlnw, 1 - s.g, s.g);
      const double r = bin.value - (p.low + jump * s.g);
      jtj += row * row.transpose();
      jtr += row * r;
    }
    for (int attempt = 0; attempt < 30; ++attempt) {
      Eigen::Matrix4d a = jtj;
      for (int i = 0; i < 4; ++i) a(i, i) += lambda * std::max(jtj(i, i), 1e-300);
      const Eigen::Vector4d step = a.ldlt().solve(jtr);
      ShockProfile trial = p;
      trial.y_s += step(0);
      trial.w *= std::exp(std::clamp(step(1), -2.0, 2.0));
      trial.low += step(2);
      trial.high += step(3);
      // The box: the front within the fitted bins, the level behind it at most twice the
      // rise to the top (the last bin must lie behind the front, so it holds at least half
      // the rise). Without it a noisy block's rising foot is fitted as the tail of a step
      // far taller and further on than the data.
      trial.y_s = std::clamp(trial.y_s, y_begin, fit.y_end);
      trial.high = std::min(trial.high, high_bound);
      const double trial_chi2 = step.allFinite() ? sum_of_squares(bins, trial) : HUGE_VAL;
      if (trial_chi2 <= chi2) {
        // Converged when the residual stops falling or the front stops moving (MINPACK's
        // relative tolerances).
        converged = chi2 - trial_chi2 <= 1e-10 * chi2 ||
                    (std::abs(step(0)) < 1e-8 * dy && std::abs(step(1)) < 1e-8);
        p = trial;
        chi2 = trial_chi2;
        lambda = std::max(lambda / 10, 1e-12);
        break;
      }
      lambda *= 10;
      if (lambda > 1e12) {  // no step lowers the residual: a minimum within rounding
        converged = true;
        break;
      }
    }
  }
  fit.profile = p;
  fit.rms = std::sqrt(chi2 / static_cast<double>(bins.size()));
  if (!converged) {
    fit.why = "the fit of the step did not converge in 500 iterations";
    return fit;
  }
  if (!(p.high >= min_jump_ratio * p.low) || !(p.high > p.low)) {
    char text[160];
    std::snprintf(text, sizeof text, "the fitted step rises from %.3g to %.3g, less than %.3g-fold",
                  p.low, p.high, min_jump_ratio);
    fit.why = text;
    return fit;
  }
  if (!(p.y_s >= y_begin && p.y_s <= fit.y_end) || !(p.w > 0 && p.w < span)) {
    fit.why = "the fitted step (y_s = " + in_mm(p.y_s) + ", w = " + in_mm(p.w) +
              ") lies outside the fitted bins (" + in_mm(y_begin) + " to " + in_mm(fit.y_end) + ")";
    return fit;
  }
  if (p.high >= high_bound) {
    fit.why =
        "the fitted step runs to its bound (a level behind the front twice the rise to "
        "the profile's top): the profile does not level off before the face";
    return fit;
  }
  // A front inside the last bin fitted leaves the level behind it unmeasured: that bin's one
  // value is then all there is of the level and the position together.
  if (bins.back().a < p.y_s) {
    fit.why = "the fitted front (y_s = " + in_mm(p.y_s) +
              ") lies in the last bin of the profile's top (" + in_mm(bins.back().a) + " to " +
              in_mm(fit.y_end) +
              "): the level behind it and its position cannot both be fitted (finer rows "
              "resolve it)";
    return fit;
  }
  fit.found = true;
  return fit;
}

}  // namespace granshock

#include "analysis/front_crossing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace granshock {

namespace {
// The bins [begin, end) of a line clamped to it; false (no front: too few bins) when fewer
// than 2 remain. Values and centres must be as long as each other.
bool clamp_search(const std::vector<double>& values, const std::vector<double>& y, int& begin,
                  int& end, const char* caller) {
  if (values.size() != y.size())
    throw std::invalid_argument(std::string(caller) + ": values and y differ in length");
  begin = std::max(begin, 0);
  end = std::min(end, static_cast<int>(values.size()));
  return end - begin >= 2;
}
}  // namespace

FrontCrossing find_front_crossing(const std::vector<double>& phi, const std::vector<double>& y,
                                  int begin, int end, double phi_up, const ThresholdRule& rule) {
  FrontCrossing c;
  if (!clamp_search(phi, y, begin, end, "find_front_crossing")) return c;
  c.why = NoFront::no_upstream_phi;
  if (!(phi_up > 0)) return c;
  for (int k = begin; k < end; ++k)
    if (std::isfinite(phi[k]) && (c.peak_index < 0 || phi[k] > c.phi_peak)) {
      c.phi_peak = phi[k];
      c.peak_index = k;
    }
  c.why = NoFront::all_masked;
  if (c.peak_index < 0) return c;
  c.why = NoFront::jump_too_small;
  if (!(c.phi_peak >= rule.min_jump_ratio * phi_up)) return c;
  c.base = phi_up;
  c.threshold = phi_up + rule.fraction * (c.phi_peak - phi_up);
  c.why = NoFront::masked_before_peak;
  for (int k = begin; k <= c.peak_index; ++k)
    if (!std::isfinite(phi[k])) return c;
  c.why = NoFront::above_threshold_first;
  if (phi[begin] >= c.threshold) return c;

  for (int k = begin + 1; k <= c.peak_index; ++k) {
    if (phi[k] >= c.threshold && phi[k - 1] < c.threshold) {
      const double t = (c.threshold - phi[k - 1]) / (phi[k] - phi[k - 1]);
      c.y_threshold = y[k - 1] + t * (y[k] - y[k - 1]);
      c.found = true;
      c.why = NoFront::none;
      break;
    }
  }
  if (!c.found) return c;

  // Steepest rise upstream of the peak.
  auto gradient = [&](int k) { return (phi[k + 1] - phi[k]) / (y[k + 1] - y[k]); };
  int best = begin;
  for (int k = begin; k < c.peak_index; ++k)
    if (gradient(k) > gradient(best)) best = k;
  const double h = y[best + 1] - y[best];
  double offset = 0;
  if (best > begin && best + 1 < c.peak_index) {
    const double gm = gradient(best - 1), g0 = gradient(best), gp = gradient(best + 1);
    const double curvature = gm - 2 * g0 + gp;
    if (curvature < 0) offset = std::clamp(0.5 * (gm - gp) / curvature, -0.5, 0.5);
  }
  c.y_max_gradient = 0.5 * (y[best] + y[best + 1]) + offset * h;
  return c;
}

FrontCrossing find_largest_rise(const std::vector<double>& values, const std::vector<double>& y,
                                int begin, int end, const ThresholdRule& rule) {
  FrontCrossing c;
  if (!clamp_search(values, y, begin, end, "find_largest_rise")) return c;
  // One pass downstream with the running minimum: the largest rise ends at the bin whose
  // value exceeds the smallest value before it by most.
  int lowest = -1, rise_from = -1;
  double rise = 0;
  for (int k = begin; k < end; ++k) {
    if (!std::isfinite(values[k])) continue;
    if (lowest >= 0 && values[k] - values[lowest] > rise) {
      rise = values[k] - values[lowest];
      rise_from = lowest;
      c.peak_index = k;
    }
    if (lowest < 0 || values[k] < values[lowest]) lowest = k;
  }
  c.why = lowest < 0 ? NoFront::all_masked : NoFront::no_rise;
  if (c.peak_index < 0) return c;
  c.base = values[rise_from];
  c.phi_peak = values[c.peak_index];
  c.why = NoFront::rise_too_small;
  if (!(c.phi_peak >= rule.min_jump_ratio * c.base)) return c;
  c.why = NoFront::masked_before_peak;
  for (int k = rise_from; k <= c.peak_index; ++k)
    if (!std::isfinite(values[k])) return c;
  c.threshold = c.base + rule.fraction * (c.phi_peak - c.base);
  int k = rise_from + 1;
  while (values[k] < c.threshold) ++k;  // stops at the peak at the latest
  const double t = (c.threshold - values[k - 1]) / (values[k] - values[k - 1]);
  c.y_threshold = y[k - 1] + t * (y[k] - y[k - 1]);
  c.found = true;
  c.why = NoFront::none;
  return c;
}

std::string describe(NoFront why, const FrontCrossing& c, double phi_up, const ThresholdRule& rule,
                     const std::string& quantity) {
  const char* q = quantity.c_str();
  char text[200];
  switch (why) {
    case NoFront::none:
      return "";
    case NoFront::too_few_bins:
      return "fewer than 2 bins to search";
    case NoFront::no_upstream_phi:
      return "no measured upstream " + quantity;
    case NoFront::all_masked:
      return "every searched bin is masked (too few particle samples)";
    case NoFront::jump_too_small:
      std::snprintf(text, sizeof text, "the largest %s (%.3g) is below %.3g %s_up (%.3g)", q,
                    c.phi_peak, rule.min_jump_ratio, q, rule.min_jump_ratio * phi_up);
      return text;
    case NoFront::masked_before_peak:
      return "a masked bin (too few particle samples) lies between the search start and the "
             "peak";
    case NoFront::no_rise:
      return quantity + " nowhere rises along the searched bins";
    case NoFront::rise_too_small:
      std::snprintf(text, sizeof text, "%s rises at most from %.3g to %.3g, less than %.3g-fold", q,
                    c.base, c.phi_peak, rule.min_jump_ratio);
      return text;
    case NoFront::above_threshold_first:
      std::snprintf(text, sizeof text,
                    "%s is already above the threshold %.3g where the search starts", q,
                    c.threshold);
      return text;
  }
  return "";
}

}  // namespace granshock

#include "detachment.hpp"

#include <cmath>
#include <limits>

#include "bin_fields.hpp"

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The shock position in one profile (pooled or one block), NaN when none is found.
double shock_position(const BinSums& profile, const FieldPhysics& phys, double phi_up, int begin,
                      int end, const ThresholdRule& rule, FrontCrossing* out = nullptr) {
  const BinFields f = compute_bin_fields(profile, phys);
  std::vector<double> y(static_cast<std::size_t>(profile.ny));
  for (int k = 0; k < profile.ny; ++k) y[static_cast<std::size_t>(k)] = profile.y_centre(k);
  const FrontCrossing c = find_front_crossing(f.phi, y, begin, end, phi_up, rule);
  if (out != nullptr) *out = c;
  return c.found ? c.y_threshold : kNaN;
}
}  // namespace

Detachment measure_detachment(const BinSums& profile, const FieldPhysics& phys, double phi_up,
                              double y_search_begin, const ThresholdRule& rule) {
  Detachment d;
  d.y_shock = d.surface = d.delta = d.delta_over_d = d.delta_err = d.delta_over_d_err = kNaN;
  d.phi_peak = d.threshold = kNaN;
  if (!phys.obstacle) return d;
  const double diameter = phys.obstacle->diameter;
  d.surface = phys.obstacle->yc - phys.obstacle->radius();
  int begin = 0, end = 0;
  while (begin < profile.ny && profile.y_centre(begin) < y_search_begin) ++begin;
  while (end < profile.ny && profile.y_centre(end) < d.surface) ++end;

  FrontCrossing pooled;
  d.y_shock = shock_position(profile.pooled_blocks(), phys, phi_up, begin, end, rule, &pooled);
  d.phi_peak = pooled.peak_index >= 0 ? pooled.phi_peak : kNaN;
  d.threshold = pooled.found ? pooled.threshold : kNaN;
  d.found = pooled.found;
  if (d.found) {
    d.delta = d.surface - d.y_shock;
    d.delta_over_d = d.delta / diameter;
  }

  std::vector<double> finite;
  for (int b = 0; b < profile.blocks; ++b) {
    if (!(profile.samples[static_cast<std::size_t>(b)] > 0))
      continue;  // a block the run never reached
    const double y = shock_position(profile.block(b), phys, phi_up, begin, end, rule);
    const double delta = d.surface - y;
    d.delta_blocks.push_back(delta);
    if (std::isfinite(delta)) finite.push_back(delta);
  }
  d.blocks_used = static_cast<int>(finite.size());
  if (d.found && d.blocks_used >= 2) {
    const double nb = d.blocks_used;
    double mean = 0, variance = 0;
    for (double v : finite) mean += v / nb;
    for (double v : finite) variance += (v - mean) * (v - mean) / (nb - 1);
    d.delta_err = std::sqrt(variance / nb);
    d.delta_over_d_err = d.delta_err / diameter;
  }
  return d;
}

}  // namespace granshock

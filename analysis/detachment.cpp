#include "detachment.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "block_error.hpp"

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string in_d(double length, const FieldPhysics& phys) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g d", length / phys.d);
  return text;
}

// The shock on one profile (pooled or one block); masked bins hold no phi. A front found
// within the rows that measured phi_up does not count (why = none, found = false).
FrontCrossing crossing(const BinSums& profile, const FieldPhysics& phys, double phi_up, int begin,
                       int end, const DetachmentSearch& search) {
  const BinFields f = compute_bin_fields(profile, phys, search.mask);
  std::vector<double> y(static_cast<std::size_t>(profile.ny)), phi = f.phi;
  for (int k = 0; k < profile.ny; ++k) y[static_cast<std::size_t>(k)] = profile.y_centre(k);
  for (std::size_t k = 0; k < phi.size(); ++k)
    if (f.masked[k]) phi[k] = kNaN;
  FrontCrossing c = find_front_crossing(phi, y, begin, end, phi_up, search.rule);
  if (c.found && c.y_threshold < search.y_upstream_end) c.found = false;
  return c;
}

// Why the crossing c of a profile gives no delta.
std::string no_front_reason(const FrontCrossing& c, const FieldPhysics& phys, double phi_up,
                            const DetachmentSearch& search) {
  if (c.why == NoFront::none)
    return "the front on the stagnation line (y = " + in_d(c.y_threshold, phys) +
           ") lies within the grid rows that measure phi_up (below y = " +
           in_d(search.y_upstream_end, phys) + ")";
  return describe(c.why, c, phi_up, search.rule);
}
}  // namespace

Detachment measure_detachment(const BinSums& profile, const FieldPhysics& phys, double phi_up,
                              double y_search_begin, const ThresholdRule& rule) {
  DetachmentSearch search;
  search.y_begin = y_search_begin;
  search.rule = rule;
  return measure_detachment(profile, phys, phi_up, search);
}

Detachment measure_detachment(const BinSums& profile, const FieldPhysics& phys, double phi_up,
                              const DetachmentSearch& search) {
  Detachment d;
  d.y_shock = d.surface = d.delta = d.delta_over_d = d.delta_err = d.delta_over_d_err = kNaN;
  d.phi_peak = d.threshold = kNaN;
  if (!phys.obstacle) {
    d.reason = d.err_reason = "the scene has no obstacle";
    return d;
  }
  const double diameter = phys.obstacle->diameter;
  d.surface = phys.obstacle->yc - phys.obstacle->radius();
  int begin = 0, end = 0;
  while (begin < profile.ny && profile.y_centre(begin) < search.y_begin) ++begin;
  while (end < profile.ny && profile.y_centre(end) < d.surface) ++end;

  const FrontCrossing pooled = crossing(profile.pooled_blocks(), phys, phi_up, begin, end, search);
  d.phi_peak = pooled.peak_index >= 0 ? pooled.phi_peak : kNaN;
  d.threshold = pooled.found ? pooled.threshold : kNaN;
  d.found = pooled.found;
  if (d.found) {
    d.y_shock = pooled.y_threshold;
    d.delta = d.surface - d.y_shock;
    d.delta_over_d = d.delta / diameter;
  } else if (pooled.why == NoFront::too_few_bins) {
    d.reason = "the stagnation-line profile holds " + std::to_string(std::max(end - begin, 0)) +
               " bins between the search start (y = " + in_d(search.y_begin, phys) +
               ") and the surface (y = " + in_d(d.surface, phys) + "); the threshold rule needs 2";
  } else {
    d.reason =
        "no shock front on the stagnation line: " + no_front_reason(pooled, phys, phi_up, search);
  }

  std::vector<double> finite;
  std::string first_failure;
  for (int b = 0; b < profile.blocks; ++b) {
    if (!(profile.samples[static_cast<std::size_t>(b)] > 0))
      continue;  // a block the run never reached
    const FrontCrossing c = crossing(profile.block(b), phys, phi_up, begin, end, search);
    const double delta = c.found ? d.surface - c.y_threshold : kNaN;
    d.delta_blocks.push_back(delta);
    if (std::isfinite(delta))
      finite.push_back(delta);
    else if (first_failure.empty())
      first_failure =
          "block " + std::to_string(b) + ": " + no_front_reason(c, phys, phi_up, search);
  }
  d.blocks_used = static_cast<int>(finite.size());
  if (!d.found) {
    d.err_reason = "delta/D itself is undeterminable";
  } else if (d.blocks_used < 2) {
    d.err_reason = "only " + std::to_string(d.blocks_used) + " of the " +
                   std::to_string(d.delta_blocks.size()) +
                   " blocks with samples show a front on the stagnation line (the error needs 2)";
    if (!first_failure.empty()) d.err_reason += "; " + first_failure;
  } else {
    d.delta_err = block_standard_error(finite);
    d.delta_over_d_err = d.delta_err / diameter;
  }
  return d;
}

}  // namespace granshock

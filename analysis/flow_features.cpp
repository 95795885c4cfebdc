#include "analysis/flow_features.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/field_analysis.hpp"

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

FlowFeatures measure_flow_features(const FieldAnalysis& a) {
  FlowFeatures f;
  f.shock_layer_phi_mean = f.hot_subsonic_fraction = kNaN;
  f.upstream_ma_peak = f.upstream_ma_peak_over_inf = f.wake_phi_over_phi_up = kNaN;
  const FieldPhysics& phys = a.physics;
  if (!phys.obstacle) {
    f.shock_layer_reason = f.hot_reason = f.upstream_ma_reason = f.wake_reason =
        "the scene has no obstacle";
    return f;
  }
  const FieldPhysics::Obstacle& c = *phys.obstacle;
  const Detachment& front = a.detachment;
  const BinFields& line = a.profile_fields;

  // Along the stagnation strip: the shock layer behind the front, the gas ahead of it.
  if (!front.found) {
    f.shock_layer_reason = f.hot_reason = f.upstream_ma_reason =
        "no delta/D, so no front to measure from: " + front.reason;
  } else {
    double sum = 0, ma_peak = kNaN;
    int bins = 0;
    const double y_begin = a.grid.y0 + a.reference_row * a.grid.dy;
    for (int k = 0; k < a.profile.ny; ++k) {
      const std::size_t i = static_cast<std::size_t>(k);
      const double y = a.profile.y_centre(k);
      if (y > front.y_shock && y < front.surface && std::isfinite(line.phi[i])) {
        sum += line.phi[i];
        ++bins;
      }
      if (y >= y_begin && y < front.y_shock && !line.masked[i] && std::isfinite(line.mach[i]) &&
          !(ma_peak >= line.mach[i]))
        ma_peak = line.mach[i];
    }
    if (bins > 0) {
      f.shock_layer_phi_mean = sum / bins;
    } else {
      f.shock_layer_reason = "no profile bin between the front and the surface";
    }
    f.upstream_ma_peak = ma_peak;
    const double ma_inf = a.upstream_inlet.mach;
    if (!std::isfinite(ma_peak))
      f.upstream_ma_reason = "no unmasked profile bin between the search start and the front";
    else if (!std::isfinite(ma_inf))
      f.upstream_ma_reason = "no Ma_inf at the inlet: " + a.upstream_inlet.reason;
    else
      f.upstream_ma_peak_over_inf = ma_peak / ma_inf;

    // The hot region on the stagnation strip: the bins from the front to the surface at or
    // above the primary front's threshold, T_min + 1/2 (T_peak - T_min). The inflow near the
    // inlet, before it cools, may be as hot and does not count.
    int subsonic = 0;
    for (int k = 0; k < a.profile.ny; ++k) {
      const std::size_t i = static_cast<std::size_t>(k);
      const double y = a.profile.y_centre(k);
      if (y < front.y_shock || y > front.surface || line.masked[i] ||
          !(line.temperature[i] >= front.threshold))
        continue;
      ++f.hot_bins;
      subsonic += line.mach[i] < 1;
    }
    if (f.hot_bins > 0)
      f.hot_subsonic_fraction = static_cast<double>(subsonic) / f.hot_bins;
    else
      f.hot_reason = "no unmasked bin of the stagnation strip is that hot";
  }

  // The wake: one frontal width D behind the obstacle, within its shadow.
  double disks = 0, area = 0;
  for (int iy = 0; iy < a.grid.ny; ++iy) {
    const double y = a.grid.y_centre(iy);
    if (y < c.back || y > c.back + c.width) continue;
    for (int ix = 0; ix < a.grid.nx; ++ix) {
      if (std::abs(phys.dx_from_axis(a.grid.x_centre(ix))) > 0.5 * c.width) continue;
      const std::size_t k = a.fields.index(iy, ix);
      if (!std::isfinite(a.fields.phi[k])) continue;
      disks += a.fields.phi[k] * a.grid.bin_area(iy);
      area += a.grid.bin_area(iy);
    }
  }
  if (!(area > 0))
    f.wake_reason = "no sampled grid bin lies within one frontal width behind the obstacle";
  else if (!(a.phi_up > 0))
    f.wake_reason = "no upstream phi beyond the strip: " + a.upstream_downstream.reason;
  else
    f.wake_phi_over_phi_up = disks / area / a.phi_up;
  return f;
}

}  // namespace granshock

#include "analysis/stagnation_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/shock_profile_fit.hpp"

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Ma falling through 1, searched from upstream: the first bin k in (begin, end) with
// Ma[k] < 1 <= Ma[k-1], interpolated linearly.
FrontFix sonic_point(const StagnationLine& line, int begin, int end) {
  FrontFix f;
  f.threshold = 1;
  f.peak = kNaN;
  const std::vector<double>& ma = line.mach;
  if (!std::isfinite(ma[static_cast<std::size_t>(begin)])) {
    f.why = "the Mach number is undetermined (masked bin) where the search starts";
    return f;
  }
  if (ma[static_cast<std::size_t>(begin)] < 1) {
    f.why = "the flow is already subsonic where the search starts";
    return f;
  }
  for (int k = begin + 1; k < end; ++k) {
    const double here = ma[static_cast<std::size_t>(k)],
                 before = ma[static_cast<std::size_t>(k - 1)];
    if (!std::isfinite(here)) {
      f.why =
          "a masked bin (too few particle samples) lies between the search start and the "
          "sonic point";
      return f;
    }
    if (here < 1 && before >= 1) {
      const double t = (1 - before) / (here - before);
      const double y0 = line.y[static_cast<std::size_t>(k - 1)],
                   y1 = line.y[static_cast<std::size_t>(k)];
      f.y = y0 + t * (y1 - y0);
      f.found = true;
      return f;
    }
  }
  f.why = "the flow stays supersonic up to the surface";
  return f;
}

// A front from one crossing (front_crossing.hpp); `what` names the quantity in reasons.
FrontFix fix_of(const FrontCrossing& c, double upstream, const ThresholdRule& rule,
                bool max_gradient, const char* what) {
  FrontFix f;
  f.peak = c.peak_index >= 0 ? c.phi_peak : kNaN;
  f.threshold = c.found ? c.threshold : kNaN;
  f.found = c.found;
  if (c.found)
    f.y = max_gradient ? c.y_max_gradient : c.y_threshold;
  else
    f.why = describe(c.why, c, upstream, rule, what);
  return f;
}

// A front from a fitted step (shock_profile_fit.hpp); the bins are as high as the first pair's
// spacing.
FrontFix fitted(const std::vector<double>& values, const std::vector<double>& y, int begin, int end,
                const ThresholdRule& rule, double window) {
  const ShockProfileFit fit =
      fit_shock_profile(values, y, y[1] - y[0], begin, end, rule.min_jump_ratio, window);
  FrontFix f;
  f.found = fit.found;
  f.peak = fit.found ? fit.profile.high : kNaN;
  f.threshold = fit.found ? 0.5 * (fit.profile.low + fit.profile.high) : kNaN;
  f.low = fit.found ? fit.profile.low : kNaN;
  f.width = fit.found ? fit.profile.w : kNaN;
  f.fit_end = fit.found ? fit.y_end : kNaN;
  if (fit.found)
    f.y = fit.profile.y_s;
  else
    f.why = fit.why;
  return f;
}
}  // namespace

const char* name(FrontDefinition d) {
  switch (d) {
    case FrontDefinition::temperature_jump:
      return "temperature_jump";
    case FrontDefinition::density_threshold:
      return "density_threshold";
    case FrontDefinition::density_max_gradient:
      return "density_max_gradient";
    case FrontDefinition::sonic_line:
      return "sonic_line";
    case FrontDefinition::temperature_fit:
      return "temperature_fit";
    case FrontDefinition::density_fit:
      return "density_fit";
  }
  return "";
}

StagnationLine stagnation_line(const BinSums& column, const FieldPhysics& phys,
                               const MaskRule& mask) {
  const BinFields f = compute_bin_fields(column, phys, mask);
  StagnationLine line;
  const std::size_t n = static_cast<std::size_t>(column.ny);
  line.y.resize(n);
  line.phi = f.phi;
  line.temperature = f.temperature;
  line.mach = f.mach;
  line.fit_window = 20 * phys.d;
  for (std::size_t k = 0; k < n; ++k) {
    line.y[k] = column.y_centre(static_cast<int>(k));
    if (f.masked[k]) line.phi[k] = line.temperature[k] = line.mach[k] = kNaN;
  }
  return line;
}

FrontFix locate_front(FrontDefinition definition, const StagnationLine& line, int begin, int end,
                      const UpstreamValues& upstream, const ThresholdRule& rule) {
  begin = std::max(begin, 0);
  end = std::min(end, static_cast<int>(line.y.size()));
  if (end - begin < 2) {
    FrontFix f;
    f.peak = f.threshold = kNaN;
    f.why = "fewer than 2 bins to search";
    return f;
  }
  switch (definition) {
    case FrontDefinition::temperature_jump:
      return fix_of(find_largest_rise(line.temperature, line.y, begin, end, rule), kNaN, rule,
                    false, "T");
    case FrontDefinition::density_threshold:
    case FrontDefinition::density_max_gradient:
      return fix_of(find_front_crossing(line.phi, line.y, begin, end, upstream.phi, rule),
                    upstream.phi, rule, definition == FrontDefinition::density_max_gradient, "phi");
    case FrontDefinition::sonic_line:
      return sonic_point(line, begin, end);
    case FrontDefinition::temperature_fit:
      return fitted(line.temperature, line.y, begin, end, rule, line.fit_window);
    case FrontDefinition::density_fit:
      return fitted(line.phi, line.y, begin, end, rule, line.fit_window);
  }
  return {};
}

BinSums strip_of(const BinSums& profile, double x_axis, double width) {
  if (profile.nx == 1) return profile;
  const int lo = static_cast<int>(std::lround((x_axis - 0.5 * width - profile.x0) / profile.dx));
  const int hi = static_cast<int>(std::lround((x_axis + 0.5 * width - profile.x0) / profile.dx));
  const int begin = std::clamp(lo, 0, profile.nx - 1);
  const int end = std::clamp(std::max(hi, begin + 1), begin + 1, profile.nx);
  return profile.columns(begin, end);
}

}  // namespace granshock

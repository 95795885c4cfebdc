// The stagnation line: the fields along one strip of the stagnation-line profile and the
// four definitions of where the shock front crosses it (docs/fields.md, section 6):
//   temperature_jump      the half-rise of the largest rise of T along the line, T_min to
//                         T_peak, searched downstream from T_min: the upstream edge of the hot
//                         region, which the paper places "between the shock front and the
//                         obstacle" (primary); the inflow cools on its way to the shock, so
//                         the rise starts from the cooled gas, not from the inlet's T_up;
//   density_threshold     phi first reaches phi_up + 1/2 (phi_peak - phi_up);
//   density_max_gradient  the steepest rise of phi upstream of its peak;
//   sonic_line            Ma first falls below 1 (the sonic line "just behind the front");
//   temperature_fit       the centre y_s of a bin-averaged tanh step fitted to T up to its
//                         peak (shock_profile_fit.hpp), with the front's thickness w;
//   density_fit           the same fit to phi.
// All search the same bins, from the reference row beyond the insertion strip to the last
// bin upstream of the obstacle's surface; the first four interpolate linearly between bin
// centres.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "analysis/front_crossing.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

enum class FrontDefinition {
  temperature_jump,
  density_threshold,
  density_max_gradient,
  sonic_line,
  temperature_fit,
  density_fit
};
inline constexpr std::array<FrontDefinition, 6> kFrontDefinitions = {
    FrontDefinition::temperature_jump,     FrontDefinition::density_threshold,
    FrontDefinition::density_max_gradient, FrontDefinition::sonic_line,
    FrontDefinition::temperature_fit,      FrontDefinition::density_fit};
inline constexpr FrontDefinition kPrimaryFront = FrontDefinition::temperature_jump;
const char* name(FrontDefinition definition);  // "temperature_jump", ...

// The measured state ahead of the shock (the grid rows beyond the strip): the density
// definitions rise from it.
struct UpstreamValues {
  double phi = 0;
};

// One column's fields, bin by bin upstream to downstream; masked bins hold NaN (phi too).
struct StagnationLine {
  std::vector<double> y, phi, temperature, mach;
  // The fitted fronts fit the bins within this distance upstream of the profile's top
  // (docs/fields.md, "The fitted front"): 20 particle diameters.
  double fit_window = HUGE_VAL;
};
StagnationLine stagnation_line(const BinSums& column, const FieldPhysics& physics,
                               const MaskRule& mask);

// Where the front crosses the line by one definition, searched in bins [begin, end).
struct FrontFix {
  bool found = false;
  double y = 0;
  double peak = 0, threshold = 0;  // of the definition's quantity (NaN: none)
  // The fitted fronts' thickness w, level upstream and cut (the downstream edge of the last
  // bin fitted); NaN for the other definitions. Their peak is the fitted level behind the
  // front and their threshold the level half-way.
  double width = std::numeric_limits<double>::quiet_NaN(),
         low = std::numeric_limits<double>::quiet_NaN(),
         fit_end = std::numeric_limits<double>::quiet_NaN();
  std::string why;  // why there is no front (empty when found)
};
FrontFix locate_front(FrontDefinition definition, const StagnationLine& line, int begin, int end,
                      const UpstreamValues& upstream, const ThresholdRule& rule);

// The columns of a stagnation-line profile within width / 2 of the axis at x_axis, added into
// one strip (a one-column profile is returned as it is: files before granshock 0.9 held one
// 4 d strip). The strip is at least one column wide.
BinSums strip_of(const BinSums& profile, double x_axis, double width);

}  // namespace granshock

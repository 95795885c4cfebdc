// Where phi rises through the shock along one line of bins, searched from upstream
// (DESIGN.md 2.3): the rule shared by the shock front (one bin column at a time) and the
// detachment length (the stagnation-line profile). Rules and reasons: docs/fields.md.
#pragma once

#include <vector>

namespace granshock {

struct ThresholdRule {
  // The front is where phi first reaches phi_up + fraction (phi_peak - phi_up).
  double fraction = 0.5;
  // A line has a front only when phi_peak >= min_jump_ratio phi_up: weaker rises are
  // noise or a fading Mach wave, not a shock.
  double min_jump_ratio = 1.5;
};

struct FrontCrossing {
  bool found = false;
  double threshold = 0;  // phi_up + fraction (phi_peak - phi_up)
  double phi_peak = 0;   // max phi over the searched bins
  int peak_index = -1;
  double y_threshold = 0;  // linear interpolation between the two bins around the crossing
  double y_max_gradient =
      0;  // steepest rise of phi between phi_up and the peak (parabolic refinement)
};

// phi and y: the bins of one line, y (bin centres) increasing downstream. Searches bins
// [begin, end): the peak is the largest finite phi there; the crossing is the first bin k
// in (begin, peak] with phi[k] >= threshold > phi[k-1], interpolated linearly; the maximum
// gradient is that of the steepest pair (k, k+1) with begin <= k < peak, placed at the
// pair's midpoint and refined by a parabola through its neighbours' gradients. Not found
// when the jump is too small, when phi is already above the threshold at `begin`, or when
// a NaN lies between `begin` and the peak.
FrontCrossing find_front_crossing(const std::vector<double>& phi, const std::vector<double>& y,
                                  int begin, int end, double phi_up, const ThresholdRule& rule);

}  // namespace granshock

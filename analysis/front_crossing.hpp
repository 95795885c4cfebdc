// Where phi rises through the shock along one line of bins, searched from upstream
// (docs/fields.md): the rule shared by the shock front (one bin column at a time) and the
// detachment length (the stagnation-line profile). Rules and reasons: docs/fields.md.
#pragma once

#include <string>
#include <vector>

namespace granshock {

struct ThresholdRule {
  // The front is where phi first reaches phi_up + fraction (phi_peak - phi_up).
  double fraction = 0.5;
  // A line has a front only when phi_peak >= min_jump_ratio phi_up: weaker rises are
  // noise or a fading Mach wave, not a shock.
  double min_jump_ratio = 1.5;
};

// Why a line has no front (docs/fields.md, "When a number cannot be determined").
enum class NoFront {
  none,                   // a front was found
  too_few_bins,           // fewer than 2 bins to search
  no_upstream_phi,        // phi_up is not a positive number
  all_masked,             // no usable (finite) phi in the searched bins
  jump_too_small,         // phi_peak < min_jump_ratio phi_up
  masked_before_peak,     // a masked (NaN) bin between the start and the peak
  above_threshold_first,  // phi already at or above the threshold where the search starts
  no_rise,                // the values only fall along the searched bins
  rise_too_small,         // the largest rise ends below min_jump_ratio times its start
};

struct FrontCrossing {
  bool found = false;
  NoFront why = NoFront::too_few_bins;
  double base = 0;       // where the rise starts from: phi_up, or the largest rise's start
  double threshold = 0;  // base + fraction (phi_peak - base)
  double phi_peak = 0;   // max phi over the searched bins (the largest rise's top)
  int peak_index = -1;
  double y_threshold = 0;  // linear interpolation between the two bins around the crossing
  double y_max_gradient =
      0;  // steepest rise of phi between phi_up and the peak (parabolic refinement)
};

// phi and y: the bins of one line, y (bin centres) increasing downstream; masked bins hold
// NaN. Searches bins [begin, end): the peak is the largest finite phi there; the crossing
// is the first bin k in (begin, peak] with phi[k] >= threshold > phi[k-1], interpolated
// linearly; the maximum gradient is that of the steepest pair (k, k+1) with begin <= k <
// peak, placed at the pair's midpoint and refined by a parabola through its neighbours'
// gradients. Not found (and `why` says which) when the jump is too small, when phi is
// already above the threshold at `begin`, or when a NaN lies between `begin` and the peak.
FrontCrossing find_front_crossing(const std::vector<double>& phi, const std::vector<double>& y,
                                  int begin, int end, double phi_up, const ThresholdRule& rule);

// The half-rise of the largest rise along a line, for a quantity that may fall ahead of the
// front and be larger far upstream than at the front: the temperature, which the inflow
// loses to inelastic collisions on its way to the shock (docs/fields.md, section 6). The
// rise is the pair of bins i < j in [begin, end) that maximises values[j] - values[i]; its
// base is values[i], its peak values[j], the threshold base + fraction (peak - base), and the
// crossing the first bin k in (i, j] with values[k] >= threshold, interpolated linearly
// from k - 1: searched downstream from the rise's start, so warmer gas upstream of the
// start does not count, nor does a dip below the threshold inside the hot layer. Not found
// when nothing rises, when peak < min_jump_ratio base, or when a NaN lies between i and j.
// No maximum gradient is measured.
FrontCrossing find_largest_rise(const std::vector<double>& values, const std::vector<double>& y,
                                int begin, int end, const ThresholdRule& rule);

// One clause saying why there is no front, e.g. "the largest phi (0.12) is below 1.5 phi_up";
// `quantity` names what was searched (the rule also serves the temperature).
std::string describe(NoFront why, const FrontCrossing& c, double phi_up, const ThresholdRule& rule,
                     const std::string& quantity = "phi");

}  // namespace granshock

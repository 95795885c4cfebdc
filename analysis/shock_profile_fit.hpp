// A fitted shock front (docs/fields.md, "The fitted front"): the profile of a quantity along
// a line of bins, from the search start to the end of its top before the obstacle's face,
// fitted by least squares (Levenberg-Marquardt on four parameters) with
//   v(y) = low + (high - low) (1 + tanh((y - y_s) / w)) / 2
// averaged over each bin: a bin holds the mean of the profile over its rows, and the integral
// of tanh is log cosh, so the model of a bin is exact for any bin size and the fitted y_s and w
// do not depend on it (where the bin value is the mean of the profile, as phi's is).
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace granshock {

struct ShockProfile {
  double y_s = 0;   // the front: where the profile is half-way from low to high, m
  double w = 0;     // the thickness (10 % to 90 % of the rise is 2.197 w), m
  double low = 0;   // the level upstream
  double high = 0;  // the level behind the front
};

// The bin-averaged model over [y_lo, y_hi].
double bin_average(const ShockProfile& p, double y_lo, double y_hi);
// The model at a point.
double profile_at(const ShockProfile& p, double y);

struct ShockProfileFit {
  bool found = false;
  ShockProfile profile;
  int points = 0;    // bins in the fit
  double y_end = 0;  // the downstream edge of the last bin fitted (the cut), m
  double rms = 0;    // root mean square residual of the fit
  std::string why;   // why there is no front (empty when found)
};

// values: bin values along the line, y: bin centres (increasing, spacing dy = the bin
// height); masked bins hold NaN and are left out. Fits bins [begin, top]: top is the last of
// the bins from the largest finite value in [begin, end) on that stay within 10 % of the
// rise (from the lowest value) below it. No front (and `why` says why) with fewer than 5
// bins in the fit, when y_s lies in the last bin fitted (the level behind the front and its
// position are then one number), when the fit does not converge, when high < min_jump_ratio low, or
// when y_s or w fall outside the fitted bins.
// Only the bins whose centre lies within `window` upstream of the top's end are fitted (the
// level ahead of the front is the level just ahead of it, and the fit's cost stays that of
// a few dozen bins).
ShockProfileFit fit_shock_profile(const std::vector<double>& values, const std::vector<double>& y,
                                  double dy, int begin, int end, double min_jump_ratio,
                                  double window = HUGE_VAL);

}  // namespace granshock

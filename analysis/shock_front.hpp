// The bow-shock front on the bin grid (docs/fields.md): for each bin column the position
// where phi rises through the threshold (front_crossing.hpp) and the position of the
// steepest rise, searched from the reference row beyond the insertion strip towards the
// obstacle; both as polylines; and the far-field shock angle on each flank.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "analysis/bin_fields.hpp"
#include "analysis/field_physics.hpp"
#include "analysis/front_crossing.hpp"
#include "analysis/polyline.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

// A straight line y = intercept + slope (x - xc) fitted by least squares to the front
// points of one flank (x - xc the minimum-image distance from the obstacle's axis), and
// the angle between it and the free stream (+y): beta = atan(1/|slope|).
struct FlankFit {
  int points = 0;
  double slope = 0, intercept = 0;
  double angle_deg = 0, angle_err_deg = 0;  // error from the slope's standard error
  double region_near = 0,
         region_far = 0;  // the fit region: region_near <= |x - xc| <= region_far, m
  std::string reason;     // why the angle is NaN (empty when it is a number)
};

struct ShockFront {
  std::vector<double> x;                                                 // column centres, m [nx]
  std::vector<double> y_threshold, y_max_gradient, phi_peak, threshold;  // NaN where no front [nx]
  std::vector<Polyline> threshold_lines, gradient_lines;  // consecutive columns with a front
  // The primary definition's front (T half-rise of the largest rise, docs/fields.md section
  // 6) per column: what the figures draw beside delta/D. NaN where no front, and in a
  // column without a phi front (y_threshold NaN): a T rise without compression is no shock.
  std::vector<double> y_temperature;
  std::vector<Polyline> temperature_lines;
  FlankFit left, right;      // x < xc and x > xc
  double angle_deg = 0;      // mean of the flanks that have a fit (NaN if none)
  std::string angle_reason;  // why angle_deg is NaN (empty when it is a number)
};

// Fit region of each flank: columns with D <= |x - xc| <= W/2 - 2 bins (one obstacle
// diameter away from the axis, where the front has become straight, and two bins short of
// the line midway to the periodic image, where the fronts of neighbouring images meet).
// A flank needs 3 points; its angle is NaN otherwise, and both are NaN without an obstacle.
// Masked bins hold no phi. A front below y_upstream_end (the upper edge of the rows that
// measured phi_up) lies within those rows and does not count.
ShockFront find_shock_front(const BinFields& fields, const BinSums& grid,
                            const FieldPhysics& physics, double phi_up, int row_begin,
                            const ThresholdRule& rule = {},
                            double y_upstream_end = -std::numeric_limits<double>::infinity());

// Least-squares line fit of (x, y) points (Eigen) and the resulting angle to +y.
FlankFit fit_flank(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace granshock

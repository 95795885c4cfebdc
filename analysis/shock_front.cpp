#include "analysis/shock_front.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <limits>

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegree = 180.0 / M_PI;

// The last row (exclusive) to search in a column: rows whose centre lies upstream of the
// obstacle's surface at the column's x; every row for columns beside the obstacle.
int search_end(const BinSums& grid, const FieldPhysics& phys, double x) {
  if (!phys.obstacle) return grid.ny;
  double surface = 0;
  if (!phys.obstacle->upstream_surface(phys.obstacle->xc + phys.dx_from_axis(x), surface))
    return grid.ny;
  int end = 0;
  while (end < grid.ny && grid.y_centre(end) < surface) ++end;
  return end;
}

std::vector<Polyline> runs_of_finite(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<Polyline> lines;
  Polyline current;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::isfinite(y[i])) {
      current.push_back({x[i], y[i]});
    } else if (!current.empty()) {
      lines.push_back(std::move(current));
      current.clear();
    }
  }
  if (!current.empty()) lines.push_back(std::move(current));
  return lines;
}
}  // namespace

FlankFit fit_flank(const std::vector<double>& x, const std::vector<double>& y) {
  FlankFit fit;
  fit.points = static_cast<int>(x.size());
  fit.slope = fit.intercept = fit.angle_deg = fit.angle_err_deg = kNaN;
  if (x.size() < 3) return fit;
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = x[static_cast<std::size_t>(i)];
    b(i) = y[static_cast<std::size_t>(i)];
  }
  const Eigen::Vector2d coef = a.colPivHouseholderQr().solve(b);
  fit.intercept = coef(0);
  fit.slope = coef(1);
  const Eigen::VectorXd residual = b - a * coef;
  const double variance = residual.squaredNorm() / static_cast<double>(n - 2);
  const Eigen::Matrix2d covariance = variance * (a.transpose() * a).inverse();
  const double slope_err = std::sqrt(std::max(covariance(1, 1), 0.0));
  // beta = atan(1/|s|): the angle between the line's direction (1, s) and +y.
  fit.angle_deg = std::atan2(1.0, std::abs(fit.slope)) * kDegree;
  fit.angle_err_deg = slope_err / (1.0 + fit.slope * fit.slope) * kDegree;
  return fit;
}

ShockFront find_shock_front(const BinFields& f, const BinSums& grid, const FieldPhysics& phys,
                            double phi_up, int row_begin, const ThresholdRule& rule,
                            double y_upstream_end) {
  ShockFront s;
  const std::size_t nx = static_cast<std::size_t>(grid.nx);
  s.x.resize(nx);
  s.y_threshold.assign(nx, kNaN);
  s.y_max_gradient.assign(nx, kNaN);
  s.phi_peak.assign(nx, kNaN);
  s.threshold.assign(nx, kNaN);
  s.y_temperature.assign(nx, kNaN);
  std::vector<double> y(static_cast<std::size_t>(grid.ny)),
      column(static_cast<std::size_t>(grid.ny)), temperature(static_cast<std::size_t>(grid.ny));
  for (int iy = 0; iy < grid.ny; ++iy) y[static_cast<std::size_t>(iy)] = grid.y_centre(iy);
  for (int ix = 0; ix < grid.nx; ++ix) {
    const std::size_t i = static_cast<std::size_t>(ix);
    s.x[i] = grid.x_centre(ix);
    for (int iy = 0; iy < grid.ny; ++iy) {
      const std::size_t k = f.index(iy, ix);
      column[static_cast<std::size_t>(iy)] = f.masked[k] ? kNaN : f.phi[k];
      temperature[static_cast<std::size_t>(iy)] = f.masked[k] ? kNaN : f.temperature[k];
    }
    const int end = search_end(grid, phys, s.x[i]);
    const FrontCrossing c = find_front_crossing(column, y, row_begin, end, phi_up, rule);
    if (!c.found || c.y_threshold < y_upstream_end) continue;
    // A shock compresses: a column whose phi does not rise has no T front either, though
    // its T may rise 1.5-2-fold where the inflow, cooled by its own collisions, meets
    // warmer gas (free-stream columns of a short run; docs/fields.md, section 5).
    const FrontCrossing hot = find_largest_rise(temperature, y, row_begin, end, rule);
    if (hot.found && hot.y_threshold >= y_upstream_end) s.y_temperature[i] = hot.y_threshold;
    s.y_threshold[i] = c.y_threshold;
    s.y_max_gradient[i] = c.y_max_gradient;
    s.phi_peak[i] = c.phi_peak;
    s.threshold[i] = c.threshold;
  }
  s.threshold_lines = runs_of_finite(s.x, s.y_threshold);
  s.gradient_lines = runs_of_finite(s.x, s.y_max_gradient);
  s.temperature_lines = runs_of_finite(s.x, s.y_temperature);

  s.left = s.right = fit_flank({}, {});
  s.angle_deg = kNaN;
  if (!phys.obstacle) {
    s.left.reason = s.right.reason = s.angle_reason = "the scene has no obstacle";
    return s;
  }
  const double near = phys.obstacle->width;
  const double far = 0.5 * (phys.box_x_hi - phys.box_x_lo) - 2 * grid.dx;
  std::vector<double> xl, yl, xr, yr;
  for (std::size_t i = 0; i < nx; ++i) {
    if (!std::isfinite(s.y_threshold[i])) continue;
    const double dx = phys.dx_from_axis(s.x[i]);
    if (std::abs(dx) < near || std::abs(dx) > far) continue;
    // Fit in axis coordinates so that a flank split by the periodic seam stays straight.
    (dx < 0 ? xl : xr).push_back(dx);
    (dx < 0 ? yl : yr).push_back(s.y_threshold[i]);
  }
  s.left = fit_flank(xl, yl);
  s.right = fit_flank(xr, yr);
  char region[160];
  std::snprintf(region, sizeof region, "%.4g d <= |x - xc| <= %.4g d", near / phys.d, far / phys.d);
  for (FlankFit* fit : {&s.left, &s.right}) {
    fit->region_near = near;
    fit->region_far = far;
    if (std::isfinite(fit->angle_deg)) continue;
    if (far < near)
      fit->reason = std::string("the domain is too narrow: the fit region ") + region +
                    " (one diameter from the axis to 2 bins short of the midway line) is empty";
    else
      fit->reason = "only " + std::to_string(fit->points) + " columns of the fit region " + region +
                    " have a shock front (the line fit needs 3)";
  }
  double sum = 0;
  int count = 0;
  for (const FlankFit* fit : {&s.left, &s.right})
    if (std::isfinite(fit->angle_deg)) {
      sum += fit->angle_deg;
      ++count;
    }
  s.angle_deg = count ? sum / count : kNaN;
  if (!count)
    s.angle_reason = s.left.reason == s.right.reason
                         ? s.left.reason
                         : "left flank: " + s.left.reason + "; right flank: " + s.right.reason;
  return s;
}

}  // namespace granshock

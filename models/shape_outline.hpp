// An obstacle's cross-section in the x-y plane, as the kernels and the host see it
// (docs/design.md, "Obstacles"): a disk, or a convex polygon given by its corners
// counter-clockwise, both about the obstacle's centre. Every shape header
// (models/cylinder.hpp, wedge.hpp, plate.hpp) describes itself by one; the force
// kernel (kernels/models/obstacle_body.hpp) finds a particle's overlap and normal from it,
// and the host functions below give the keep-out distance and the free area of a slab.
// Plain C++ without Kokkos, so that core/, io/ and analysis/ can ask it too.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace granshock {

struct ShapeOutline {
  static constexpr int kMaxCorners = 4;
  enum class Kind { disk, polygon };
  Kind kind = Kind::disk;
  double radius = 0;  // disk
  // A sphere (models/sphere.hpp): the disk is its cut through the centre, and in 3-D the
  // force kernel measures from the centre along z too.
  bool ball = false;
  int corners = 0;  // polygon: 3 or 4, counter-clockwise
  std::array<std::array<double, 2>, kMaxCorners> corner{};
};

namespace outline_detail {

inline double cross(double ax, double ay, double bx, double by) {
  return ax * by - ay * bx;
}

// The outward unit normal of the polygon's edge e (corners counter-clockwise).
inline std::array<double, 2> edge_normal(const ShapeOutline& s, int e) {
  const auto& a = s.corner[e];
  const auto& b = s.corner[(e + 1) % s.corners];
  const double ex = b[0] - a[0], ey = b[1] - a[1], len = std::hypot(ex, ey);
  return {ey / len, -ex / len};
}

// Widens [lo, hi] by where the line at height y crosses the convex polygon `p`.
inline void widen_by_polygon(const std::vector<std::array<double, 2>>& p, double y, double& lo,
                             double& hi) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    if ((a[1] - y) * (b[1] - y) > 0) continue;
    if (a[1] == b[1]) {
      lo = std::min({lo, a[0], b[0]});
      hi = std::max({hi, a[0], b[0]});
    } else {
      const double x = a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  }
}

}  // namespace outline_detail

// The outline as a closed polygon about the centre (cx, cy), counter-clockwise, without
// repeating its first point: a polygon's corners, or a disk as a regular polygon of
// `disk_segments` corners on its circle (what a viewer draws: run.xmf, fields.xmf).
inline std::vector<std::array<double, 2>> outline_points(const ShapeOutline& s, double cx,
                                                         double cy, int disk_segments = 72) {
  std::vector<std::array<double, 2>> points;
  if (s.kind == ShapeOutline::Kind::disk) {
    for (int k = 0; k < disk_segments; ++k) {
      const double a = 2 * M_PI * k / disk_segments;
      points.push_back({cx + s.radius * std::cos(a), cy + s.radius * std::sin(a)});
    }
  } else {
    for (int c = 0; c < s.corners; ++c)
      points.push_back({cx + s.corner[c][0], cy + s.corner[c][1]});
  }
  return points;
}

// The signed distance of the point (x, y), relative to the centre, from the outline:
// negative inside.
inline double outline_distance(const ShapeOutline& s, double x, double y) {
  using namespace outline_detail;
  if (s.kind == ShapeOutline::Kind::disk) return std::hypot(x, y) - s.radius;
  double outside = std::numeric_limits<double>::infinity(), deepest = -outside;
  for (int e = 0; e < s.corners; ++e) {
    const auto& a = s.corner[e];
    const auto& b = s.corner[(e + 1) % s.corners];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double t =
        std::clamp(((x - a[0]) * ex + (y - a[1]) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
    outside = std::min(outside, std::hypot(x - a[0] - t * ex, y - a[1] - t * ey));
    const auto n = edge_normal(s, e);
    deepest = std::max(deepest, (x - a[0]) * n[0] + (y - a[1]) * n[1]);
  }
  return deepest <= 0 ? deepest : outside;
}

// What the host asks of a shape, derived here from its outline and nowhere else, so that
// the frontal width (the D of delta/D), the length along the flow, the area and the
// upstream surface cannot disagree with the cross-section the kernels collide with
// (tests/shapes/test_obstacle_geometry.cpp checks them against each shape's closed forms
// and against outline_distance).

// The extent along x (across the flow; `axis` 0) or y (along it; `axis` 1).
inline double outline_extent(const ShapeOutline& s, int axis) {
  if (s.kind == ShapeOutline::Kind::disk) return 2 * s.radius;
  double lo = s.corner[0][axis], hi = lo;
  for (int c = 1; c < s.corners; ++c) {
    lo = std::min(lo, s.corner[c][axis]);
    hi = std::max(hi, s.corner[c][axis]);
  }
  return hi - lo;
}

// The area of the cross-section: pi R^2, or the polygon's by the shoelace formula.
inline double outline_area(const ShapeOutline& s) {
  if (s.kind == ShapeOutline::Kind::disk) return M_PI * s.radius * s.radius;
  double twice = 0;
  for (int c = 0; c < s.corners; ++c) {
    const auto& a = s.corner[c];
    const auto& b = s.corner[(c + 1) % s.corners];
    twice += outline_detail::cross(a[0], a[1], b[0], b[1]);
  }
  return 0.5 * twice;
}

// The upstream (lowest y) point of the outline at the lateral offset x from the centre,
// relative to the centre; false where the line x = const misses the outline.
inline bool outline_upstream_surface(const ShapeOutline& s, double x, double& y) {
  if (s.kind == ShapeOutline::Kind::disk) {
    if (!(std::abs(x) < s.radius)) return false;
    y = -std::sqrt(s.radius * s.radius - x * x);
    return true;
  }
  bool found = false;
  for (int c = 0; c < s.corners; ++c) {
    const auto& a = s.corner[c];
    const auto& b = s.corner[(c + 1) % s.corners];
    if ((a[0] - x) * (b[0] - x) > 0 || a[0] == b[0]) continue;
    const double at = a[1] + (x - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
    if (!found || at < y) y = at;
    found = true;
  }
  return found;
}

// The area of the polygon grown by `clearance` (the points within `clearance` of it)
// between the heights y_lo and y_hi, relative to the centre. The grown polygon is the
// union of the polygon, a disk at each corner and a rectangle on each edge, so its chord
// at a height spans the chords of those pieces; the chord length is integrated by
// Gauss-Legendre between the heights where a piece begins or ends.
inline double polygon_kept_out_area(const ShapeOutline& s, double clearance, double y_lo,
                                    double y_hi) {
  using namespace outline_detail;
  const double c = clearance;
  std::vector<std::vector<std::array<double, 2>>> pieces;
  std::vector<double> breaks;
  pieces.emplace_back(s.corner.begin(), s.corner.begin() + s.corners);
  for (int e = 0; e < s.corners; ++e) {
    const auto& a = s.corner[e];
    const auto& b = s.corner[(e + 1) % s.corners];
    const auto n = edge_normal(s, e);
    pieces.push_back(
        {a, b, {b[0] + c * n[0], b[1] + c * n[1]}, {a[0] + c * n[0], a[1] + c * n[1]}});
    for (const auto& q : pieces.back()) breaks.push_back(q[1]);
    breaks.push_back(a[1] - c);
    breaks.push_back(a[1] + c);
  }
  const auto chord = [&](double y) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : pieces) widen_by_polygon(p, y, lo, hi);
    for (int k = 0; k < s.corners; ++k) {
      const double dy = y - s.corner[k][1];
      if (std::abs(dy) > c) continue;
      const double half = std::sqrt(c * c - dy * dy);
      lo = std::min(lo, s.corner[k][0] - half);
      hi = std::max(hi, s.corner[k][0] + half);
    }
    return hi > lo ? hi - lo : 0.0;
  };
  breaks.push_back(y_lo);
  breaks.push_back(y_hi);
  std::sort(breaks.begin(), breaks.end());
  // 5-point Gauss-Legendre on 64 sub-intervals of each piece-wise smooth interval.
  static constexpr double node[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                     0.5384693101056831, 0.9061798459386640};
  static constexpr double weight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                       0.4786286704993665, 0.2369268850561891};
  constexpr int kSub = 64;
  double area = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = std::max(breaks[i], y_lo), b = std::min(breaks[i + 1], y_hi);
    if (!(b > a)) continue;
    const double h = (b - a) / kSub;
    for (int k = 0; k < kSub; ++k) {
      const double mid = a + (k + 0.5) * h;
      for (int q = 0; q < 5; ++q) area += 0.5 * h * weight[q] * chord(mid + 0.5 * h * node[q]);
    }
  }
  return area;
}

// The area of the slab y in [y_lo, y_hi] (relative to the centre) within `clearance` of
// the outline: what insertion's keep-out zone takes from the inflow's free area. A disk
// grown by the clearance is a disk of radius rho, whose area between two horizontal lines
// is G(y_hi) - G(y_lo) with G(t) = t sqrt(rho^2 - t^2) + rho^2 asin(t/rho).
inline double outline_kept_out_area(const ShapeOutline& s, double clearance, double y_lo,
                                    double y_hi) {
  if (s.kind == ShapeOutline::Kind::polygon) return polygon_kept_out_area(s, clearance, y_lo, y_hi);
  const double rho = s.radius + clearance;
  const auto G = [rho](double t) {
    t = std::clamp(t, -rho, rho);
    return t * std::sqrt(rho * rho - t * t) + rho * rho * std::asin(t / rho);
  };
  return G(y_hi) - G(y_lo);
}

}  // namespace granshock

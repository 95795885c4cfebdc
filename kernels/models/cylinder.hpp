// The cylinder obstacle (docs/design.md, "Obstacles"), its axis along z: everything that
// depends on its shape, in one type. The force kernel takes its outline, a disk
// (kernels/models/obstacle_body.hpp); insertion keeps centres out of the disk grown by a
// clearance, the inflow asks for the area that takes from a slab of the domain, and the
// analysis for its frontal width (the D of delta/D), its upstream surface and its area.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "kernels/models/shape_outline.hpp"

namespace granshock {

struct CylinderShape {
  static constexpr ObstacleShape kind = ObstacleShape::cylinder;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key = "obstacle.diameter";  // as refusals name D

  static double radius(const Obstacle& o) { return 0.5 * o.diameter_m; }

  static ShapeOutline outline(const Obstacle& o) {
    ShapeOutline s;
    s.kind = ShapeOutline::Kind::disk;
    s.radius = radius(o);
    return s;
  }
  static double frontal_width(const Obstacle& o) { return o.diameter_m; }
  static double streamwise_length(const Obstacle& o) { return o.diameter_m; }
  static double area(const Obstacle& o) { return M_PI * radius(o) * radius(o); }
  // The upstream surface at a lateral offset dx from the axis (|dx| < R), from the centre.
  static double upstream_surface(const Obstacle& o, double dx) {
    return -std::sqrt(radius(o) * radius(o) - dx * dx);
  }

  // The part of the slab y in [y_lo, y_hi] within `clearance` of the surface: a disk of
  // radius rho = R + clearance centred at yc, whose area between two horizontal lines is
  // G(y_hi - yc) - G(y_lo - yc) with G(t) = t sqrt(rho^2 - t^2) + rho^2 asin(t/rho).
  static double kept_out_area(const Obstacle& o, double clearance, double y_lo, double y_hi) {
    const double rho = radius(o) + clearance;
    const double yc = o.centre[1];
    const auto G = [rho](double t) {
      t = std::clamp(t, -rho, rho);
      return t * std::sqrt(rho * rho - t * t) + rho * rho * std::asin(t / rho);
    };
    return G(y_hi - yc) - G(y_lo - yc);
  }
};

}  // namespace granshock

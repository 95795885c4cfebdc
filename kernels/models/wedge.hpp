// The wedge obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, [obstacle]): a
// symmetric triangular prism along z, its tip upstream on the axis x = centre, half-angle
// theta at the tip, `length` L from the tip to the base that closes it; the centre is the
// middle of that length. Its outline is the triangle tip (0, -L/2), base corners
// (+-L tan theta, L/2); the force kernel finds the closest point on it
// (kernels/models/obstacle_body.hpp), and the rest follows from the triangle.
#pragma once

#include <cmath>

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "kernels/models/shape_outline.hpp"

namespace granshock {

struct WedgeShape {
  static constexpr ObstacleShape kind = ObstacleShape::wedge;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key =  // as refusals name D
      "frontal width 2 obstacle.length tan(obstacle.half_angle)";

  // Half the base: L tan theta.
  static double half_base(const Obstacle& o) {
    return o.length_m * std::tan(o.half_angle_deg * M_PI / 180);
  }

  static ShapeOutline outline(const Obstacle& o) {
    const double h = half_base(o), l = 0.5 * o.length_m;
    ShapeOutline s;
    s.kind = ShapeOutline::Kind::polygon;
    s.corners = 3;
    s.corner = {{{0, -l}, {h, l}, {-h, l}, {0, 0}}};
    return s;
  }
  static double frontal_width(const Obstacle& o) { return 2 * half_base(o); }
  static double streamwise_length(const Obstacle& o) { return o.length_m; }
  static double area(const Obstacle& o) { return half_base(o) * o.length_m; }
  // The face at a lateral offset dx (|dx| < L tan theta): |dx| / tan theta behind the tip.
  static double upstream_surface(const Obstacle& o, double dx) {
    return -0.5 * o.length_m + std::abs(dx) / std::tan(o.half_angle_deg * M_PI / 180);
  }
  static double kept_out_area(const Obstacle& o, double clearance, double y_lo, double y_hi) {
    return polygon_kept_out_area(outline(o), clearance, y_lo - o.centre[1], y_hi - o.centre[1]);
  }
};

}  // namespace granshock

// The wedge obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, [obstacle]): a
// symmetric triangular prism along z, its tip upstream on the axis x = centre, half-angle
// theta at the tip, `length` L from the tip to the base that closes it; the centre is the
// middle of that length. Its outline is the triangle tip (0, -L/2), base corners
// (+-L tan theta, L/2); the force kernel finds the closest point on it
// (kernels/models/obstacle_body.hpp), and every measure follows from the triangle
// (models/shape_outline.hpp).
#pragma once

#include <cmath>

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "models/shape_key.hpp"
#include "models/shape_outline.hpp"

namespace granshock {

struct WedgeShape {
  static constexpr ObstacleShape kind = ObstacleShape::wedge;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key =  // as refusals name D
      "frontal width 2 obstacle.length tan(obstacle.half_angle)";
  static constexpr ShapeKey keys[] = {
      {"half_angle", ShapeKey::Kind::angle, "the half-angle theta at the upstream tip", 0, 90},
      {"length", ShapeKey::Kind::length,
       "tip to base, along the flow; the base is 2 length tan(theta) wide"},
  };

  static double half_angle_deg(const Obstacle& o) { return o.size[0]; }
  static double length(const Obstacle& o) { return o.size[1]; }
  // Half the base: L tan theta.
  static double half_base(const Obstacle& o) {
    return length(o) * std::tan(half_angle_deg(o) * M_PI / 180);
  }

  static ShapeOutline outline(const Obstacle& o) {
    const double h = half_base(o), l = 0.5 * length(o);
    ShapeOutline s;
    s.kind = ShapeOutline::Kind::polygon;
    s.corners = 3;
    s.corner = {{{0, -l}, {h, l}, {-h, l}, {0, 0}}};
    return s;
  }
};

}  // namespace granshock

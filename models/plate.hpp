// The plate obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, [obstacle]): a
// rectangular prism along z facing the flow, `width` across it and `thickness` along it,
// centred on the centre. Its outline is the rectangle; the force kernel finds the closest
// point on it (kernels/models/obstacle_body.hpp), so a particle at a corner is pushed away
// from the corner, one at a face along the face's normal.
#pragma once

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "models/shape_key.hpp"
#include "models/shape_outline.hpp"

namespace granshock {

struct PlateShape {
  static constexpr ObstacleShape kind = ObstacleShape::plate;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key = "obstacle.width";  // as refusals name D
  static constexpr ShapeKey keys[] = {
      {"width", ShapeKey::Kind::length, "the plate across the flow (its D)"},
      {"thickness", ShapeKey::Kind::length, "the plate along the flow"},
  };

  static double width(const Obstacle& o) { return o.size[0]; }
  static double thickness(const Obstacle& o) { return o.size[1]; }

  static ShapeOutline outline(const Obstacle& o) {
    const double w = 0.5 * width(o), t = 0.5 * thickness(o);
    ShapeOutline s;
    s.kind = ShapeOutline::Kind::polygon;
    s.corners = 4;
    s.corner = {{{-w, -t}, {w, -t}, {w, t}, {-w, t}}};
    return s;
  }
};

}  // namespace granshock

// The square obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, [obstacle]): a
// square prism along z of side `side`, turned by `rotation` degrees about its axis: at 0 a
// face meets the flow (a plate of equal width and thickness), at 45 a corner does (a
// diamond, whose frontal width is side sqrt(2)). Its outline is the turned square; the
// force kernel finds the closest point on it (kernels/models/obstacle_body.hpp), and every
// measure follows from the outline (models/shape_outline.hpp). Added as the
// proof that a shape is one header (docs/design.md, "Adding an obstacle shape").
#pragma once

#include <cmath>

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "models/shape_key.hpp"
#include "models/shape_outline.hpp"

namespace granshock {

struct SquareShape {
  static constexpr ObstacleShape kind = ObstacleShape::square;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key =  // as refusals name D
      "frontal width of obstacle.side at obstacle.rotation";
  static constexpr ShapeKey keys[] = {
      {"side", ShapeKey::Kind::length, "the square's side"},
      {"rotation", ShapeKey::Kind::angle,
       "turned about its axis: 0 a face upstream, 45 a corner upstream", 0, 90, true, 0.0},
  };

  static double side(const Obstacle& o) { return o.size[0]; }
  static double rotation_deg(const Obstacle& o) { return o.size[1]; }

  static ShapeOutline outline(const Obstacle& o) {
    // The corners (+-h, +-h) turned counter-clockwise by the rotation; at 0 exactly the
    // plate's corners (cos 0 = 1 and sin 0 = 0 exactly).
    const double h = 0.5 * side(o), a = rotation_deg(o) * M_PI / 180;
    const double c = std::cos(a), s = std::sin(a);
    ShapeOutline out;
    out.kind = ShapeOutline::Kind::polygon;
    out.corners = 4;
    const double unturned[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
    for (int k = 0; k < 4; ++k)
      out.corner[k] = {c * unturned[k][0] - s * unturned[k][1],
                       s * unturned[k][0] + c * unturned[k][1]};
    return out;
  }
};

}  // namespace granshock

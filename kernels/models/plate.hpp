// The plate obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, [obstacle]): a
// rectangular prism along z facing the flow, `width` across it and `thickness` along it
// (a square block when the two are equal), centred on the centre. Its outline is the
// rectangle; the force kernel finds the closest point on it
// (kernels/models/obstacle_body.hpp), so a particle at a corner is pushed away from the
// corner, one at a face along the face's normal.
#pragma once

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "kernels/models/shape_outline.hpp"

namespace granshock {

struct PlateShape {
  static constexpr ObstacleShape kind = ObstacleShape::plate;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key = "obstacle.width";  // as refusals name D

  static ShapeOutline outline(const Obstacle& o) {
    const double w = 0.5 * o.width_m, t = 0.5 * o.thickness_m;
    ShapeOutline s;
    s.kind = ShapeOutline::Kind::polygon;
    s.corners = 4;
    s.corner = {{{-w, -t}, {w, -t}, {w, t}, {-w, t}}};
    return s;
  }
  static double frontal_width(const Obstacle& o) { return o.width_m; }
  static double streamwise_length(const Obstacle& o) { return o.thickness_m; }
  static double area(const Obstacle& o) { return o.width_m * o.thickness_m; }
  static double upstream_surface(const Obstacle& o, double) { return -0.5 * o.thickness_m; }
  static double kept_out_area(const Obstacle& o, double clearance, double y_lo, double y_hi) {
    return polygon_kept_out_area(outline(o), clearance, y_lo - o.centre[1], y_hi - o.centre[1]);
  }
};

}  // namespace granshock

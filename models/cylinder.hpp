// The cylinder obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, [obstacle]): a
// circular cylinder with its axis along z, of diameter `diameter`. Its outline is the disk;
// the force kernel keeps the cylinder's own arithmetic for it
// (kernels/models/obstacle_body.hpp), and every measure follows from the disk
// (models/shape_outline.hpp).
#pragma once

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "models/shape_key.hpp"
#include "models/shape_outline.hpp"

namespace granshock {

struct CylinderShape {
  static constexpr ObstacleShape kind = ObstacleShape::cylinder;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key = "obstacle.diameter";  // as refusals name D
  static constexpr ShapeKey keys[] = {
      {"diameter", ShapeKey::Kind::length, "the cylinder's diameter D"},
  };

  static double diameter(const Obstacle& o) { return o.size[0]; }

  static ShapeOutline outline(const Obstacle& o) {
    ShapeOutline s;
    s.kind = ShapeOutline::Kind::disk;
    s.radius = 0.5 * diameter(o);
    return s;
  }
};

}  // namespace granshock

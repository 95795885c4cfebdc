// The sphere obstacle (docs/design.md, "Obstacles"; docs/scene_format.md, "Three
// dimensions"): a sphere of diameter `diameter` centred on the centre, its z centre the
// middle of the layer. Its outline is the disk of its cut through the centre, marked
// `ball`: in 3-D the force kernel measures a particle's distance from the centre along all
// three axes (kernels/models/obstacle_body.hpp); in a quasi-2-D scene, whose particles lie
// in that plane, the sphere is exactly that disk. The host's measures (frontal width, area,
// upstream surface) are the cut's, which is where a 3-D run's fields are sampled.
#pragma once

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "models/cylinder.hpp"
#include "models/shape_key.hpp"
#include "models/shape_outline.hpp"

namespace granshock {

struct SphereShape {
  static constexpr ObstacleShape kind = ObstacleShape::sphere;
  static constexpr const char* name = choice_name(kind);
  static constexpr const char* width_key = "obstacle.diameter";  // as refusals name D
  static constexpr ShapeKey keys[] = {
      {"diameter", ShapeKey::Kind::length, "the sphere's diameter D"},
  };

  static double diameter(const Obstacle& o) { return o.size[0]; }

  // The cylinder's disk, marked as a ball.
  static ShapeOutline outline(const Obstacle& o) {
    ShapeOutline s = CylinderShape::outline(o);
    s.ball = true;
    return s;
  }
};

}  // namespace granshock

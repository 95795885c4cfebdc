// The fixed obstacle of a scene (docs/design.md, "Obstacles"): its shape, where it is, how
// large and of what material. It acts on particles like a LIGGGHTS wall, with infinite
// mass and radius in the contact law (R* = r_i, m* = m_i); the contact geometry, the
// keep-out zone of insertion and the free area of the inflow belong to the shape's type
// (kernels/models/cylinder.hpp).
#pragma once

#include <array>

#include "core/material.hpp"

namespace granshock {

// A cylinder with its axis along z, the paper's obstacle; a sphere (3-D scenes) would be
// the next entry.
enum class ObstacleShape { cylinder };

struct Obstacle {
  ObstacleShape shape = ObstacleShape::cylinder;
  std::array<double, 3> centre{0, 0, 0};
  double diameter_m = 0;
  Material material;

  double radius_m() const { return 0.5 * diameter_m; }
};

}  // namespace granshock

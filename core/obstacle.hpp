// The fixed obstacle of a scene (docs/design.md, "Obstacles"): its shape, where it is, how
// large and of what material. It acts on particles like a LIGGGHTS wall, with infinite
// mass and radius in the contact law (R* = r_i, m* = m_i). What depends on the shape (the
// contact geometry, the keep-out zone of insertion, the free area of the inflow, the
// frontal width and upstream face the analysis asks for) belongs to the shape's header
// in kernels/models/ (cylinder.hpp, wedge.hpp, plate.hpp; kernels/models/obstacle_shapes.hpp
// asks the right one).
#pragma once

#include <array>

#include "core/material.hpp"

namespace granshock {

// Prisms with their axis along z, the flow along +y (docs/scene_format.md, [obstacle]).
enum class ObstacleShape { cylinder, wedge, plate };

struct Obstacle {
  ObstacleShape shape = ObstacleShape::cylinder;
  // The middle of the shape's extent along x and y (a cylinder's axis).
  std::array<double, 3> centre{0, 0, 0};
  double diameter_m = 0;  // cylinder
  Material material;
  double half_angle_deg = 0;  // wedge: the half-angle at its upstream tip
  double length_m = 0;        // wedge: tip to base, along the flow
  double width_m = 0;         // plate: across the flow
  double thickness_m = 0;     // plate: along the flow
};

}  // namespace granshock

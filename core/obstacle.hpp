// The fixed obstacle of a scene (docs/design.md, "Obstacles"): its shape, where it is, how
// large and of what material. It acts on particles like a LIGGGHTS wall, with infinite
// mass and radius in the contact law (R* = r_i, m* = m_i). What depends on the shape (the
// contact geometry, the keep-out zone of insertion, the free area of the inflow, the
// frontal width and upstream face the analysis asks for) follows from the shape's header
// in models/ (cylinder.hpp, wedge.hpp, plate.hpp, square.hpp, sphere.hpp: its size keys and its
// outline; models/obstacle_shapes.hpp asks the right one).
#pragma once

#include <array>

#include "core/material.hpp"

namespace granshock {

// Prisms with their axis along z, the flow along +y (docs/scene_format.md, [obstacle]).
// The sphere is the one shape that is not a prism (models/sphere.hpp).
enum class ObstacleShape { cylinder, wedge, plate, square, sphere };

// The most size keys a shape has (a wedge's half-angle and length, a plate's width and
// thickness, a square's side and rotation).
inline constexpr int kMaxShapeSizes = 3;

struct Obstacle {
  ObstacleShape shape = ObstacleShape::cylinder;
  // The middle of the shape's extent along x and y (a cylinder's axis); in 3-D z is the
  // middle of the layer (a sphere's centre).
  std::array<double, 3> centre{0, 0, 0};
  // The shape's sizes in the order of its header's `keys` (metres, or degrees for an
  // angle): read them through the shape's accessors (CylinderShape::diameter(o), ...).
  std::array<double, kMaxShapeSizes> size{};
  Material material;
};

}  // namespace granshock

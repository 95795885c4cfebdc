// A fixed cylinder with its axis along z (DESIGN.md 2.1): it acts on particles like a
// LIGGGHTS wall, with infinite mass and radius in the contact law (R* = r_i, m* = m_i),
// but its surface is the cylinder's, so the overlap and normal are radial.
#pragma once

#include <array>

#include "material.hpp"

namespace granshock {

struct CylinderObstacle {
  std::array<double, 3> centre{0, 0, 0};
  double diameter_m = 0;
  Material material;
};

}  // namespace granshock

// Where a 3-D scene's field bins lie along z (docs/fields.md, "Three dimensions"): columns
// through the whole layer (a slab, or any scene without a sphere), or a cut one bin thick
// through a sphere's centre, where the flow past it is the flow in its axial plane.
#pragma once

#include <array>

#include "core/scene.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

// {z0, depth}: the columns span [z0, z0 + depth); {0, 0} in 2-D.
inline std::array<double, 2> sampled_z_range(const Scene& s) {
  if (s.setup.dim != 3) return {0, 0};
  if (s.setup.obstacle && obstacle_outline(*s.setup.obstacle).ball)
    return {s.setup.obstacle->centre[2] - 0.5 * s.bin_size_m, s.bin_size_m};
  return {s.setup.box.lo[2], s.setup.box.length(2)};
}

}  // namespace granshock

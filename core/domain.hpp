// The simulation box: per axis an interval [lo, hi) that is periodic or open.
#pragma once

#include <array>

namespace granshock {

// What bounds a 3-D scene's layer along z (docs/scene_format.md, "Three dimensions"): flat
// frictionless walls (SolverSetup::z_walls) or a periodic axis.
enum class ZBoundary { walls, periodic };

struct Box {
  std::array<double, 3> lo{0, 0, 0};
  std::array<double, 3> hi{1, 1, 1};
  std::array<bool, 3> periodic{false, false, false};

  double length(int d) const { return hi[d] - lo[d]; }
};

}  // namespace granshock

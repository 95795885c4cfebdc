// A scene without obstacle (docs/design.md, "Obstacles"): the shape that is not there.
#pragma once

#include <Kokkos_Core.hpp>
#include <optional>

#include "core/obstacle.hpp"
#include "kernels/device/position.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

// A scene without obstacle: nothing touches, nothing is kept out, and the kernels that
// ask compile to nothing.
struct NoObstacle {
  static constexpr const char* name = "no-obstacle";
  static constexpr bool present = false;
  static bool matches(const std::optional<Obstacle>& o) { return !o; }

  template <int Dim, class Real>
  struct Geometry {
    static Geometry from(const std::optional<Obstacle>&) { return {}; }
    KOKKOS_FORCEINLINE_FUNCTION bool touches(const Vec<Dim, Position>&, Real, Real&,
                                             Vec<Dim, Real>&) const {
      return false;
    }
    KOKKOS_FORCEINLINE_FUNCTION bool keeps_out(Position, Position, Real) const { return false; }
    KOKKOS_FORCEINLINE_FUNCTION bool contains(const Vec<Dim, Position>&) const { return false; }
  };
};

}  // namespace granshock

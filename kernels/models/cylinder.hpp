// The cylinder obstacle (docs/design.md, "Obstacles"), its axis along z: everything that
// depends on its shape, in one type. The force kernel asks for the overlap and normal of a
// touching particle, insertion for the keep-out zone around it, the inflow for the area
// that zone takes from a slab of the domain.
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <optional>

#include "device/device_math.hpp"
#include "device/position.hpp"
#include "device/vec.hpp"
#include "obstacle.hpp"
#include "variant_names.hpp"

namespace granshock {

struct CylinderShape {
  static constexpr const char* name = choice_name(ObstacleShape::cylinder);
  static constexpr bool present = true;
  static bool matches(const std::optional<Obstacle>& o) {
    return o && o->shape == ObstacleShape::cylinder;
  }

  // Positions and the centre are Position (double); a particle's offset from the axis is
  // formed in Position and rounded to Real, the rest is Real (device/position.hpp).
  template <int Dim, class Real>
  struct Geometry {
    Vec<Dim, Position> centre;  // in 3-D centre[2] is ignored (the axis is along z)
    Real radius;

    static Geometry from(const std::optional<Obstacle>& o) {
      Geometry g;
      for (int d = 0; d < Dim; ++d) g.centre[d] = Position(o->centre[d]);
      g.radius = Real(o->radius_m());
      return g;
    }

    // Forced inline, like every per-pair or per-particle function of the force kernel: an
    // outlined call here was a large share of a step (docs/benchmarks.md, "Old against
    // new: the restructuring, and inlining"; cli.force_kernel_helpers_are_inlined checks it).
    // A particle of radius r at x touches the surface when its distance from the axis is
    // below r + R: then dn = r + R - |x - x_c| and n is the radial unit vector.
    KOKKOS_FORCEINLINE_FUNCTION bool touches(const Vec<Dim, Position>& x, Real r, Real& dn,
                                             Vec<Dim, Real>& n) const {
      Vec<Dim, Real> dx = to_real<Real>(x - centre);
      if constexpr (Dim == 3) dx[2] = 0;
      const Real r2 = dot(dx, dx);
      const Real reach = r + radius;
      if (r2 >= reach * reach) return false;
      const Real dist = dmath::sqrt(r2);
      n = (Real(1) / dist) * dx;
      dn = reach - dist;
      return true;
    }

    // Insertion places no centre within `clearance` of the surface.
    KOKKOS_FORCEINLINE_FUNCTION bool keeps_out(Position x0, Position x1, Real clearance) const {
      const Position cx = x0 - centre[0], cy = x1 - centre[1];
      const Position reach = Position(radius + clearance);
      return cx * cx + cy * cy < reach * reach;
    }
  };

  // The part of the slab y in [y_lo, y_hi] that keeps_out(clearance) takes away: a disk of
  // radius rho = R + clearance centred at yc, whose area between two horizontal lines is
  // G(y_hi - yc) - G(y_lo - yc) with G(t) = t sqrt(rho^2 - t^2) + rho^2 asin(t/rho).
  static double kept_out_area(const std::optional<Obstacle>& o, double clearance, double y_lo,
                              double y_hi) {
    const double rho = o->radius_m() + clearance;
    const double yc = o->centre[1];
    const auto G = [rho](double t) {
      t = std::clamp(t, -rho, rho);
      return t * std::sqrt(rho * rho - t * t) + rho * rho * std::asin(t / rho);
    };
    return G(y_hi - yc) - G(y_lo - yc);
  }
};

}  // namespace granshock

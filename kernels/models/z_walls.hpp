// The flat walls of a 3-D slab (docs/design.md, "Three dimensions"): the box's faces at
// z = lo and z = hi hold the particles in a layer, as the walls of the paper's quasi-2-D
// runs did. They are frictionless, of the obstacle's material and restitution in a scene
// (SolverSetup::wall_pair), a contact with R* = r_i and m* = m_i like the obstacle's
// (docs/scene_format.md, `domain.z_boundary`).
#pragma once

#include <Kokkos_Core.hpp>

#include "core/solver_setup.hpp"
#include "kernels/device/position.hpp"

namespace granshock {

struct ZWalls {
  bool on = false;
  Position lo = 0, hi = 0;

  static ZWalls from(const SolverSetup& s) {
    ZWalls w;
    w.on = s.z_walls;
    w.lo = Position(s.box.lo[2]);
    w.hi = Position(s.box.hi[2]);
    return w;
  }

  // Whether a particle of radius r at height z touches the lower (side 0) or upper (side 1)
  // wall: then dn is the overlap and nz the z component of the unit normal from the wall to
  // the particle (+1 at the lower wall, -1 at the upper).
  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION bool touches(int side, Position z, Real r, Real& dn, Real& nz) const {
    const Real gap = side == 0 ? Real(z - lo) : Real(hi - z);
    if (gap >= r) return false;
    dn = r - gap;
    nz = side == 0 ? Real(1) : Real(-1);
    return true;
  }
};

}  // namespace granshock

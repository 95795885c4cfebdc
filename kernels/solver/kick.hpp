// The kicks of velocity Verlet (velocity_verlet.hpp), written once so that every
// integrator that uses them (the split halves, the fused step, the restitution
// calibration's reduced pair) rounds alike:
//   translation: v += dt/2 (f/m + g)
//   rotation:    w += dt/2 tau/I
#pragma once

#include <Kokkos_Core.hpp>

namespace granshock {

template <class Real>
KOKKOS_FORCEINLINE_FUNCTION void half_kick(Real& v, const Real half, const Real f,
                                           const Real inv_mass, const Real g) {
  v += half * (f * inv_mass + g);
}

template <class Real>
KOKKOS_FORCEINLINE_FUNCTION void half_spin_kick(Real& w, const Real half, const Real torque,
                                                const Real inv_inertia) {
  w += half * torque * inv_inertia;
}

}  // namespace granshock

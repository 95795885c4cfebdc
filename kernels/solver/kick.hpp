// The kicks of velocity Verlet (velocity_verlet.hpp), written once so that every
// integrator that uses them (the split halves, the fused step, the restitution
// calibration's reduced pair) rounds alike:
//   translation: v += dt/2 (f/m + g)
//   rotation:    w += dt/2 tau/I (about z in 2-D, per component in 3-D)
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/vec.hpp"

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

// 3-D: the same per component of the spin vector.
template <class Real>
KOKKOS_FORCEINLINE_FUNCTION void half_spin_kick(Vec<3, Real>& w, const Real half,
                                                const Vec<3, Real>& torque,
                                                const Real inv_inertia) {
  for (int c = 0; c < 3; ++c) w[c] += half * torque[c] * inv_inertia;
}

}  // namespace granshock

// Angular velocity and torque in the kernels: about z in 2-D, a scalar (quasi-2-D
// spheres spin in the plane of motion only), a vector in 3-D. Spin<Dim, Real> is the
// value a kernel holds; a View stores spin_components(Dim) values per particle
// (core/solver_state.hpp: a rank-1 View in 2-D, View<Real*[3]> in 3-D,
// particles/particle_store.hpp).
// load_spin and store_spin read and write one particle's spin whatever the dimension,
// so that the force kernel and the integrators are written once; in 2-D they are the
// plain scalar reads and writes they replace, and the 2-D arithmetic is unchanged.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/vec.hpp"

namespace granshock {

template <int Dim, class Real>
struct SpinOf {
  static_assert(Dim == 3, "spins are scalars in 2-D and vectors in 3-D");
  using type = Vec<3, Real>;
};
template <class Real>
struct SpinOf<2, Real> {
  using type = Real;
};

template <int Dim, class Real>
using Spin = typename SpinOf<Dim, Real>::type;

template <int Dim, class Real>
KOKKOS_FORCEINLINE_FUNCTION Spin<Dim, Real> zero_spin() {
  if constexpr (Dim == 2) {
    return Real(0);
  } else {
    return Vec<3, Real>::zero();
  }
}

template <int Dim, class View>
KOKKOS_FORCEINLINE_FUNCTION Spin<Dim, typename View::non_const_value_type> load_spin(const View& w,
                                                                                     const int i) {
  if constexpr (Dim == 2) {
    return w(i);
  } else {
    Vec<3, typename View::non_const_value_type> s;
    for (int c = 0; c < 3; ++c) s[c] = w(i, c);
    return s;
  }
}

template <int Dim, class View>
KOKKOS_FORCEINLINE_FUNCTION void store_spin(
    const View& w, const int i, const Spin<Dim, typename View::non_const_value_type>& s) {
  if constexpr (Dim == 2) {
    w(i) = s;
  } else {
    for (int c = 0; c < 3; ++c) w(i, c) = s[c];
  }
}

// |w|^2 of one particle's spin, summed in double (the diagnostics' energies).
template <int Dim, class View>
KOKKOS_FORCEINLINE_FUNCTION double spin_square(const View& w, const int i) {
  if constexpr (Dim == 2) {
    return double(w(i)) * double(w(i));
  } else {
    double s = 0;
    for (int c = 0; c < 3; ++c) s += double(w(i, c)) * double(w(i, c));
    return s;
  }
}

}  // namespace granshock

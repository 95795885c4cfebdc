// Small fixed-size vector used inside kernels: Vec<Dim, Real>.
// Dimension and precision are template parameters so that 2-D and 3-D, float and
// double kernels come from one source.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/device_math.hpp"

namespace granshock {

template <int Dim, class Real>
struct Vec {
  Real c[Dim];

  KOKKOS_INLINE_FUNCTION static Vec zero() {
    Vec v;
    for (int d = 0; d < Dim; ++d) v.c[d] = Real(0);
    return v;
  }
  KOKKOS_INLINE_FUNCTION Real& operator[](int d) { return c[d]; }
  KOKKOS_INLINE_FUNCTION const Real& operator[](int d) const { return c[d]; }

  KOKKOS_INLINE_FUNCTION Vec& operator+=(const Vec& o) {
    for (int d = 0; d < Dim; ++d) c[d] += o.c[d];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator-=(const Vec& o) {
    for (int d = 0; d < Dim; ++d) c[d] -= o.c[d];
    return *this;
  }
};

template <int Dim, class Real>
KOKKOS_INLINE_FUNCTION Vec<Dim, Real> operator+(Vec<Dim, Real> a, const Vec<Dim, Real>& b) {
  return a += b;
}
template <int Dim, class Real>
KOKKOS_INLINE_FUNCTION Vec<Dim, Real> operator-(Vec<Dim, Real> a, const Vec<Dim, Real>& b) {
  return a -= b;
}
template <int Dim, class Real>
KOKKOS_INLINE_FUNCTION Vec<Dim, Real> operator*(Real s, Vec<Dim, Real> a) {
  for (int d = 0; d < Dim; ++d) a.c[d] *= s;
  return a;
}
template <int Dim, class Real>
KOKKOS_INLINE_FUNCTION Real dot(const Vec<Dim, Real>& a, const Vec<Dim, Real>& b) {
  Real s = 0;
  for (int d = 0; d < Dim; ++d) s += a.c[d] * b.c[d];
  return s;
}
// |a|^2, the same value as dot(a, a) (0 + a square is that square, both >= +0) with one
// addition fewer: the compiler may not drop the 0 + itself.
template <int Dim, class Real>
KOKKOS_INLINE_FUNCTION Real norm2(const Vec<Dim, Real>& a) {
  Real s = a.c[0] * a.c[0];
  for (int d = 1; d < Dim; ++d) s += a.c[d] * a.c[d];
  return s;
}

// a x b (3-D: spins, torques).
template <class Real>
KOKKOS_INLINE_FUNCTION Vec<3, Real> cross(const Vec<3, Real>& a, const Vec<3, Real>& b) {
  Vec<3, Real> c;
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
  return c;
}

}  // namespace granshock

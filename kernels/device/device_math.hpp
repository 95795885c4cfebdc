// Math functions callable from host and device code for float and double.
// The C library names (sqrt/sqrtf, ...) are device functions under CUDA and host
// functions elsewhere, and they exist in Kokkos 3.4 and 4.x alike.
#pragma once

#include <Kokkos_Core.hpp>
#include <cmath>

namespace granshock::dmath {

KOKKOS_INLINE_FUNCTION double sqrt(double x) {
  return ::sqrt(x);
}
KOKKOS_INLINE_FUNCTION float sqrt(float x) {
  return ::sqrtf(x);
}
KOKKOS_INLINE_FUNCTION double rint(double x) {
  return ::rint(x);
}
KOKKOS_INLINE_FUNCTION float rint(float x) {
  return ::rintf(x);
}
KOKKOS_INLINE_FUNCTION double floor(double x) {
  return ::floor(x);
}
KOKKOS_INLINE_FUNCTION float floor(float x) {
  return ::floorf(x);
}
KOKKOS_INLINE_FUNCTION double log(double x) {
  return ::log(x);
}
KOKKOS_INLINE_FUNCTION double cos(double x) {
  return ::cos(x);
}
KOKKOS_INLINE_FUNCTION double sin(double x) {
  return ::sin(x);
}

// True unless x is NaN or infinite (x - x is NaN for both); portable to every backend
// and Kokkos version, unlike isfinite, which moved between Kokkos namespaces.
KOKKOS_INLINE_FUNCTION bool is_finite(double x) {
  return x - x == 0.0;
}

template <class T>
KOKKOS_INLINE_FUNCTION T max(T a, T b) {
  return a > b ? a : b;
}
template <class T>
KOKKOS_INLINE_FUNCTION T min(T a, T b) {
  return a < b ? a : b;
}

}  // namespace granshock::dmath

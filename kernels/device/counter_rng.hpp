// Counter-based random numbers: a value is a pure function of (seed, stream, counter),
// so a run is reproducible from its seed whatever the thread count or backend, and a
// kernel can draw numbers for particle i without shared generator state.
// The mixing function is the SplitMix64 finaliser (Steele, Lea & Flood, OOPSLA 2014).
#pragma once

#include <Kokkos_Core.hpp>
#include <cstdint>

#include "kernels/device/device_math.hpp"

namespace granshock {

KOKKOS_INLINE_FUNCTION std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

struct CounterRng {
  std::uint64_t seed = 0;

  KOKKOS_INLINE_FUNCTION std::uint64_t bits(std::uint64_t stream, std::uint64_t counter) const {
    return splitmix64(splitmix64(seed ^ splitmix64(stream)) ^ splitmix64(~counter));
  }
  // Uniform in [0, 1) with 53 random bits.
  KOKKOS_INLINE_FUNCTION double uniform(std::uint64_t stream, std::uint64_t counter) const {
    return double(bits(stream, counter) >> 11) * (1.0 / 9007199254740992.0);
  }
  // Standard normal by Box-Muller; uses counters 2k and 2k+1.
  KOKKOS_INLINE_FUNCTION double normal(std::uint64_t stream, std::uint64_t k) const {
    const double u1 = 1.0 - uniform(stream, 2 * k);  // in (0, 1]
    const double u2 = uniform(stream, 2 * k + 1);
    return dmath::sqrt(-2.0 * dmath::log(u1)) * dmath::cos(2.0 * M_PI * u2);
  }
};

}  // namespace granshock

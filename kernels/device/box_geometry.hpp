// The device-side view of a Box (core/domain.hpp): minimum-image displacements and
// periodic wrapping inside kernels. Kept apart from domain.hpp so that host-only code
// (the scene parser) does not include Kokkos.
#pragma once

#include <Kokkos_Core.hpp>
#include <limits>

#include "core/domain.hpp"
#include "kernels/device/device_math.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

// Device-side view of a Box. Minimum-image displacement without a branch per axis:
// inv_length is 0 on open axes, so the correction term vanishes there.
template <int Dim, class Real>
struct BoxGeometry {
  Real lo[Dim];
  Real length[Dim];
  Real inv_length[Dim];    // 1/length on periodic axes, 0 on open ones
  Real image_length[Dim];  // length on periodic axes, 0 on open ones
  // Half the length on periodic axes; on open ones the largest Real, so that
  // nearby_image's comparisons there are never true: with 0 they were true for every
  // other pair, a branch the CPU mispredicted at half the pairs of an open axis
  // (docs/benchmarks.md, "The paper case against the gas at the same N").
  Real half_image[Dim];

  static BoxGeometry from(const Box& box) {
    BoxGeometry g;
    for (int d = 0; d < Dim; ++d) {
      g.lo[d] = Real(box.lo[d]);
      g.length[d] = Real(box.length(d));
      g.inv_length[d] = box.periodic[d] ? Real(1.0 / box.length(d)) : Real(0);
      g.image_length[d] = box.periodic[d] ? g.length[d] : Real(0);
      g.half_image[d] =
          box.periodic[d] ? Real(0.5) * g.image_length[d] : std::numeric_limits<Real>::max();
    }
    return g;
  }

  KOKKOS_INLINE_FUNCTION Vec<Dim, Real> minimum_image(Vec<Dim, Real> dx) const {
    for (int d = 0; d < Dim; ++d) dx[d] -= length[d] * dmath::rint(dx[d] * inv_length[d]);
    return dx;
  }

  // The same for a displacement between two particles near the box (|dx| < 1.5 length,
  // as between list partners: positions are wrapped at every list build and drift less
  // than the skin until the next). Two selects per axis instead of a rounding, which
  // without SSE4.1 is a library call; where the nearest image is unambiguous (every pair
  // closer than half the box) the result is bitwise that of minimum_image. On an open axis
  // nothing is done (adding 0 changed nothing either).
  KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> nearby_image(Vec<Dim, Real> dx) const {
    for (int d = 0; d < Dim; ++d) {
      if (dx[d] > half_image[d]) dx[d] -= image_length[d];
      if (dx[d] < -half_image[d]) dx[d] += image_length[d];
    }
    return dx;
  }

  // Maps a coordinate on a periodic axis back into [lo, lo + length).
  // Coordinates already inside are returned unchanged (bitwise), so wrapping a sorted,
  // wrapped state again is the identity; resumed runs rely on that.
  KOKKOS_INLINE_FUNCTION Real wrap(int d, Real x) const {
    if (inv_length[d] == Real(0)) return x;
    if (x >= lo[d] && x - lo[d] < length[d]) return x;
    Real shifted = x - lo[d];
    shifted -= length[d] * dmath::floor(shifted * inv_length[d]);
    if (shifted >= length[d]) shifted -= length[d];  // round-off at the upper edge
    return lo[d] + shifted;
  }
};

}  // namespace granshock

// Kernels that change which particles exist: deletion of particles that left through an
// open boundary (stable compaction) and insertion of new particles in a region without
// overlaps. Both keep the arrays' capacity, so no allocation happens in steady state.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/box_geometry.hpp"
#include "kernels/device/counter_rng.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

// Face a particle left through (2 d + 1 for the upper face of axis d), or -1.
template <int Dim, class Real>
struct EscapeTest {
  Real lo[Dim];
  Real hi[Dim];
  bool check[Dim];  // open axes of a scene that deletes escaped particles

  template <class PositionView>
  KOKKOS_INLINE_FUNCTION int face(const PositionView& x, int i) const {
    for (int d = 0; d < Dim; ++d) {
      if (!check[d]) continue;
      if (x(i, d) < lo[d]) return 2 * d;
      if (x(i, d) >= hi[d]) return 2 * d + 1;
    }
    return -1;
  }
};

// Builds order = indices of the kept particles, in their current order (a stable
// compaction), and counts the escaped ones per face. Returns the kept count. One scan
// tests every particle; it writes the escaped ones' indices into the rest of `order`
// (from its end: a position order(kept) onwards, never one a kept particle takes), so the
// count per face reads only those: a stream that leaves a few particles at each list
// build does not pay a pass over all particles per face.
template <int Dim, class Real, class ExecSpace, class PositionView, class OrderView>
int compact_escaped(const EscapeTest<Dim, Real>& test, const PositionView& x, int n,
                    const OrderView& order, long (&per_face)[2 * Dim]) {
  using Policy = Kokkos::RangePolicy<ExecSpace>;
  int kept = 0;
  Kokkos::parallel_scan(
      "population::compact", Policy(0, n),
      KOKKOS_LAMBDA(const int i, int& running, const bool final) {
        const bool keep = test.face(x, i) < 0;
        if (final) {
          if (keep)
            order(running) = i;
          else
            order(n - 1 - (i - running)) = i;  // the (i - running)-th escaped one
        }
        running += keep ? 1 : 0;
      },
      kept);
  for (int f = 0; f < 2 * Dim; ++f) {
    long count = 0;
    if (kept < n)
      Kokkos::parallel_reduce(
          "population::count_escaped", Policy(kept, n),
          KOKKOS_LAMBDA(const int k, long& acc) { acc += test.face(x, order(k)) == f ? 1 : 0; },
          count);
    per_face[f] = count;
  }
  return kept;
}

// Candidate positions for an insertion, drawn from the counter RNG: candidate k of
// event e uses stream (tag, e) and counters 2k, 2k+1, so the result is the same on
// every backend and thread count.
struct InsertionStreams {
  static constexpr std::uint64_t tag = 0x494e534552540000ULL;  // "INSERT"
  KOKKOS_INLINE_FUNCTION static std::uint64_t position(std::uint64_t event) {
    return tag ^ (2 * event);
  }
  KOKKOS_INLINE_FUNCTION static std::uint64_t velocity(std::uint64_t event) {
    return tag ^ (2 * event + 1);
  }
  // 3-D: the z coordinate and velocity, from streams of their own, so that x, y and the
  // in-plane velocities are the draws a 2-D run makes. A tag that differs from `tag` in
  // its top byte: no event below 2^55 gives a stream of the 2-D ones.
  static constexpr std::uint64_t depth_tag = 0x5a494e5345525400ULL;  // "ZINSERT"
  KOKKOS_INLINE_FUNCTION static std::uint64_t depth_position(std::uint64_t event) {
    return depth_tag ^ (2 * event);
  }
  KOKKOS_INLINE_FUNCTION static std::uint64_t depth_velocity(std::uint64_t event) {
    return depth_tag ^ (2 * event + 1);
  }
};

// Species of the k-th inserted particle of a run: a Weyl sequence u_k = frac(k phi)
// (phi = golden ratio) read against the cumulative number fractions, so any fractions
// are met deterministically with an error that shrinks like log(k)/k.
template <class CumulativeView>
KOKKOS_INLINE_FUNCTION int species_for(const CumulativeView& cumulative, long k) {
  const double golden = 0.6180339887498949;
  const double product = double(k + 1) * golden;
  const double u = product - dmath::floor(product);
  const int n = int(cumulative.extent(0));
  for (int s = 0; s < n - 1; ++s)
    if (u < cumulative(s)) return s;
  return n - 1;
}

}  // namespace granshock

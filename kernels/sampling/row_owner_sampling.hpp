// Field sampling by row owners (ScatterStrategy::rows; docs/fields.md, "Cost of
// sampling"): the grid and the stagnation-line profile together, in two passes.
// LocateSampleBins finds each particle's grid and profile bin once (over the particles, as
// every kernel). RowOwnerSamplePass then runs one thread per owner; owner t takes the
// particles in its band of rows and adds their moments and contact virial (the step's
// last force pass recorded it: docs/fields.md, "The contact virial") to the bin without
// atomics. The bands follow the particle order: the particles are sorted by cell, rows of
// cells along x, at each list build, so band t's particles are mostly those that thread t
// of every other kernel advances, and are in its cache. Each bin belongs to one band and
// its particles are added in particle order, so the sums are bitwise the same for any
// thread count.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/sampling/bin_accumulator.hpp"
#include "kernels/sampling/owner_band.hpp"

namespace granshock {

template <class PositionView, class Bins, int Dim>
struct LocateSampleBins {
  GridIndex grid, profile;
  bool with_profile;
  PositionView x;
  Bins bins;  // (i, 0): grid, (i, 1): profile; -1 outside

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const double xi = double(x(i, 0)), yi = double(x(i, 1));
    int row = 0;
    bins(i, 0) = grid(xi, yi, row);
    bins(i, 1) = with_profile ? profile(xi, yi, row) : -1;
    if constexpr (Dim == 3) {
      if (!grid.holds_z(double(x(i, 2)))) bins(i, 0) = -1;  // outside the columns (3-D)
      if (!profile.holds_z(double(x(i, 2)))) bins(i, 1) = -1;
    }
  }
};

template <class ExecSpace, class Part, class PositionView, class Bins>
struct RowOwnerSamplePass {
  using Sums = Kokkos::View<double*, typename ExecSpace::memory_space>;

  Part grid, profile;  // SampleContribution<GridIndex, ...> of each layout
  Sums grid_sums, profile_sums;
  PositionView x;
  Bins bins;  // LocateSampleBins's
  int n, owners;

  // A sample's bins are cold (evicted in the 100 or so steps since the last): the owner
  // requests the bins of a batch of its particles first, so that their cache misses
  // overlap, then adds the batch in particle order.
  static constexpr int batch = 16;

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    int grid_first, grid_end, profile_first, profile_end;  // band t, as ranges of bins
    band(t, grid.where, grid_first, grid_end);
    band(t, profile.where, profile_first, profile_end);
    PlainAdd<Sums> to_grid{grid_sums}, to_profile{profile_sums};
    for (int first = 0; first < n; first += batch) {
      const int count = n - first < batch ? n - first : batch;
      int grid_bin[batch], profile_bin[batch];
      for (int b = 0; b < count; ++b) {
        const int g = bins(first + b, 0), q = bins(first + b, 1);
        grid_bin[b] = g >= grid_first && g < grid_end ? g : -1;
        profile_bin[b] = q >= profile_first && q < profile_end ? q : -1;
        if (grid_bin[b] >= 0) grid.prefetch_bin(grid_sums, grid_bin[b]);
        if (profile_bin[b] >= 0) profile.prefetch_bin(profile_sums, profile_bin[b]);
      }
      for (int b = 0; b < count; ++b) {
        const int i = first + b;
        const auto virial_of = [&](int k) { return grid.virial(i, k); };
        if (grid_bin[b] >= 0) grid.add_to_bin(grid_bin[b], i, to_grid, virial_of);
        if (profile_bin[b] >= 0) profile.add_to_bin(profile_bin[b], i, to_profile, virial_of);
      }
    }
  }

  // Owner t's band of `layout` as the bins [first, end).
  KOKKOS_INLINE_FUNCTION void band(int t, const GridIndex& layout, int& first, int& end) const {
    int lo, hi;
    owner_band(
        t, owners, n, layout.ny, [&](int i) { return layout.row_of(double(x(i, 1))); }, lo, hi);
    first = lo * layout.nx;
    end = hi * layout.nx;
  }
};

}  // namespace granshock

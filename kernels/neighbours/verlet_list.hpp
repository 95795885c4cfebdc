// Full Verlet neighbour list (each pair appears for both particles) in compressed-row
// form. A full list lets each particle sum its own force without atomics, which keeps
// results identical for any thread count; contacts are rare in a granular gas, so the
// doubled pair checks cost little. The list holds every partner within
// r_i + r_j + skin and stays valid until some particle has moved more than skin/2.
// Cells and separations are in Position (double, device/position.hpp), radii and skin in
// the variant's Real.
#pragma once

#include <Kokkos_Core.hpp>
#include <type_traits>
#include <vector>

#include "kernels/device/backends.hpp"
#include "kernels/device/box_geometry.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/device/position.hpp"
#include "kernels/device/share.hpp"
#include "kernels/device/space_alloc.hpp"
#include "kernels/device/vec.hpp"
#include "kernels/neighbours/cell_grid.hpp"

namespace granshock {

// The cells of the ghosts appended after the n owned particles (several processes,
// particles/slab_exchange.hpp): cell c's ghosts are [begin(c), end(c)). Owned cells and
// ghost cells are disjoint, so a cell's candidates keep their (cell, id) order.
template <class Mem>
struct GhostCells {
  Kokkos::View<int*, Mem> start;  // ncell + 1, relative to `offset`
  int offset = 0;                 // the owned count
  KOKKOS_INLINE_FUNCTION int begin(int c) const { return offset + start(c); }
  KOKKOS_INLINE_FUNCTION int end(int c) const { return offset + start(c + 1); }
};
// One process: no ghosts; the ghost loop compiles away.
struct NoGhostCells {
  KOKKOS_INLINE_FUNCTION int begin(int) const { return 0; }
  KOKKOS_INLINE_FUNCTION int end(int) const { return 0; }
};

template <int Dim, class Real, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
class VerletList {
  static_assert(paths_possible<ExecSpace, Paths>(), "host paths need host-accessible memory");

 public:
  using Mem = typename ExecSpace::memory_space;
  using Policy = Kokkos::RangePolicy<ExecSpace>;

  Kokkos::View<int*, Mem> offsets;     // n + 1; neighbours of i: [offsets(i), offsets(i+1))
  Kokkos::View<int*, Mem> neighbours;  // particle indices
  int total = 0;
  // Host paths: visit the candidates once, into a buffer per thread (build_visiting_once);
  // false, or device paths, visit them twice, to count and to fill. The lists are the same.
  bool visit_once = true;

  // Restores a list saved by a checkpoint.
  void assign(const std::vector<int>& host_offsets, const std::vector<int>& host_neighbours) {
    offsets = Kokkos::View<int*, Mem>("verlet_offsets", host_offsets.size() + 16);
    neighbours = Kokkos::View<int*, Mem>("verlet_neighbours", host_neighbours.size() + 64);
    auto o = host_mirror<Paths>(offsets);
    auto nb = host_mirror<Paths>(neighbours);
    for (std::size_t i = 0; i < host_offsets.size(); ++i) o(i) = host_offsets[i];
    for (std::size_t k = 0; k < host_neighbours.size(); ++k) nb(k) = host_neighbours[k];
    Kokkos::deep_copy(offsets, o);
    Kokkos::deep_copy(neighbours, nb);
    total = int(host_neighbours.size());
  }

  // Particles must be sorted by cell: cell c holds indices [cell_start(c), cell_start(c+1)),
  // and its ghosts (if any) [ghosts.begin(c), ghosts.end(c)).
  template <class PositionView, class SpeciesView, class RadiusView, class StartView,
            class Ghosts = NoGhostCells>
  void build(const CellGrid<Dim, Position>& grid, const BoxGeometry<Dim, Position>& box,
             const StartView& cell_start, const PositionView& x, const SpeciesView& species,
             const RadiusView& radius, Real skin, int n, const Ghosts& ghosts = {}) {
    if (int(offsets.extent(0)) < n + 1)
      offsets = Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("verlet_offsets"), n + n / 4 + 16);
    if constexpr (Paths::host) {
      if (visit_once)
        return build_visiting_once(grid, box, cell_start, x, species, radius, skin, n, ghosts);
    }
    auto off = offsets;
    // Pass 1: count. Pass 2: fill. Both visit the same candidates in the same order.
    Kokkos::parallel_for(
        "verlet::count", Policy(0, n), KOKKOS_LAMBDA(const int i) {
          int count = 0;
          visit(grid, box, cell_start, ghosts, x, species, radius, skin, i, [&](int) { ++count; });
          off(i + 1) = count;
        });
    int sum = 0;
    Kokkos::parallel_scan(
        "verlet::offsets", Policy(0, n + 1),
        KOKKOS_LAMBDA(const int i, int& running, const bool final) {
          const int count = i == 0 ? 0 : off(i);
          running += count;
          if (final) off(i) = running;
        },
        sum);
    total = sum;
    if (int(neighbours.extent(0)) < total)
      neighbours =
          Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("verlet_neighbours"), total + total / 4 + 64);
    auto nb = neighbours;
    Kokkos::parallel_for(
        "verlet::fill", Policy(0, n), KOKKOS_LAMBDA(const int i) {
          int k = off(i);
          visit(grid, box, cell_start, ghosts, x, species, radius, skin, i,
                [&](int j) { nb(k++) = j; });
        });
  }

  // The list in one visit of the candidates, as a hand-written OpenMP build does it
  // (docs/design.md, "The solver"): each of `shares` work items (one per thread)
  // takes a contiguous share of the particles and writes their partners into its own part
  // of a buffer, then a second, light pass turns the counts into offsets and copies each
  // part into place. The count pass of the two-visit build, which computes every
  // candidate's distance a second time, is gone. A part too small for its share's
  // partners (the first build, or the scene got denser) is counted to the end, and the
  // visit repeats with parts large enough; parts keep a quarter in reserve.
  template <class PositionView, class SpeciesView, class RadiusView, class StartView, class Ghosts>
  void build_visiting_once(const CellGrid<Dim, Position>& grid,
                           const BoxGeometry<Dim, Position>& box, const StartView& cell_start,
                           const PositionView& x, const SpeciesView& species,
                           const RadiusView& radius, Real skin, int n, const Ghosts& ghosts) {
    const int shares = ExecSpace().concurrency();
    if (int(share_count_.extent(0)) < shares)
      share_count_ = Kokkos::View<long*, Mem>(alloc_on<ExecSpace>("verlet_share_count"), shares);
    if (part_capacity_ == 0) part_capacity_ = 8L * (n / shares + 1) + 256;
    auto off = offsets;
    auto count = share_count_;
    for (;;) {
      if (long(parts_.extent(0)) < part_capacity_ * shares)
        parts_ = Kokkos::View<int*, Mem>(alloc_uninitialised_on<ExecSpace>("verlet_parts"),
                                         part_capacity_ * shares);
      auto parts = parts_;
      const long capacity = part_capacity_;
      Kokkos::parallel_for(
          "verlet::visit", Policy(0, shares), KOKKOS_LAMBDA(const int s) {
            const long first_slot = s * capacity, end_slot = first_slot + capacity;
            long k = first_slot;
            const int end = share_begin(n, s + 1, shares);
            for (int i = share_begin(n, s, shares); i < end; ++i) {
              const long before = k;
              visit(grid, box, cell_start, ghosts, x, species, radius, skin, i, [&](int j) {
                if (k < end_slot) parts(k) = j;
                ++k;
              });
              off(i + 1) = int(k - before);
            }
            count(s) = k - first_slot;
          });
      Kokkos::fence();
      long largest = 0, sum = 0;
      for (int s = 0; s < shares; ++s) {
        largest = count(s) > largest ? count(s) : largest;
        sum += count(s);
      }
      if (largest <= part_capacity_) {
        total = int(sum);
        break;
      }
      part_capacity_ = largest + largest / 4 + 256;
    }
    if (int(neighbours.extent(0)) < total)
      neighbours =
          Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("verlet_neighbours"), total + total / 4 + 64);
    auto nb = neighbours;
    auto parts = parts_;
    const long capacity = part_capacity_;
    Kokkos::parallel_for(
        "verlet::place", Policy(0, shares), KOKKOS_LAMBDA(const int s) {
          long base = 0;
          for (int r = 0; r < s; ++r) base += count(r);
          if (s == 0) off(0) = 0;
          long running = base;
          const int end = share_begin(n, s + 1, shares);
          for (int i = share_begin(n, s, shares); i < end; ++i) {
            running += off(i + 1);
            off(i + 1) = int(running);
          }
          const long first_slot = s * capacity;
          for (long k = 0; k < count(s); ++k) nb(base + k) = parts(first_slot + k);
        });
  }

 private:
  Kokkos::View<long*, Mem> share_count_;  // partners per share, build_visiting_once
  Kokkos::View<int*, Mem> parts_;         // one part of part_capacity_ per share
  long part_capacity_ = 0;

  template <class PositionView, class SpeciesView, class RadiusView, class StartView, class Ghosts,
            class F>
  KOKKOS_INLINE_FUNCTION static void visit(const CellGrid<Dim, Position>& grid,
                                           const BoxGeometry<Dim, Position>& box,
                                           const StartView& cell_start, const Ghosts& ghosts,
                                           const PositionView& x, const SpeciesView& species,
                                           const RadiusView& radius, Real skin, int i, F&& action) {
    int c[Dim];
    Vec<Dim, Position> xi;
    for (int d = 0; d < Dim; ++d) {
      xi[d] = x(i, d);
      c[d] = grid.coord(d, xi[d]);
    }
    const Real ri = radius(species(i));
    const auto candidates = [&](int begin, int end) {
      for (int j = begin; j < end; ++j) {
        if (j == i) continue;
        Vec<Dim, Position> image;
        for (int d = 0; d < Dim; ++d) image[d] = xi[d] - x(j, d);
        const Vec<Dim, Real> dx = to_real<Real>(box.minimum_image(image));
        const Real cut = ri + radius(species(j)) + skin;
        if (dot(dx, dx) < cut * cut) action(j);
      }
    };
    if constexpr (std::is_same_v<Ghosts, NoGhostCells>) {
      // Without ghosts, the three cells of a row along x (flat indices f, f + 1, f + 2)
      // hold adjacent ranges of the sorted particles: unless the row wraps or an open
      // edge cuts it, they are one range, visited in the same order as cell by cell
      // (the neighbours' order: x fastest). A third of the cell lookups.
      if (c[0] >= 1 && c[0] + 1 < grid.ncell[0]) {
        for (int row = 0; row < CellGrid<Dim, Position>::neighbour_count() / 3; ++row) {
          const int first = grid.neighbour(c, 3 * row);  // the row's cell at x - 1
          if (first >= 0) candidates(cell_start(first), cell_start(first + 3));
        }
        return;
      }
    }
    for (int k = 0; k < CellGrid<Dim, Position>::neighbour_count(); ++k) {
      const int cell = grid.neighbour(c, k);
      if (cell < 0) continue;
      candidates(cell_start(cell), cell_start(cell + 1));
      candidates(ghosts.begin(cell), ghosts.end(cell));
    }
  }
};

}  // namespace granshock

// Counting sort of particles by cell. Produces cell_start (offsets of each cell's
// particles in cell order) and order (order[k] = current index of the k-th particle in
// cell order). Within a cell particles are ordered by global id, so the result does not
// depend on the order in which threads arrived: runs are reproducible for any thread
// count and backend.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/space_alloc.hpp"
#include "kernels/neighbours/cell_grid.hpp"

namespace granshock {

// Real: the coordinate type of the grid and positions (Position in the solver).
template <int Dim, class Real, class ExecSpace>
class CellSort {
 public:
  using Mem = typename ExecSpace::memory_space;
  using Policy = Kokkos::RangePolicy<ExecSpace>;

  Kokkos::View<int*, Mem> cell_start;  // ncell + 1 offsets
  Kokkos::View<int*, Mem> order;       // cell-ordered particle indices

  template <class PositionView, class IdView>
  void sort(const CellGrid<Dim, Real>& grid, const PositionView& x, const IdView& id, int n) {
    const int ncell = grid.total();
    if (int(cell_start.extent(0)) != ncell + 1) {
      cell_start = Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("cell_start"), ncell + 1);
      fill_ = Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("cell_fill"), ncell);
    }
    if (int(order.extent(0)) < n) {
      order = Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("cell_order"), n + n / 4 + 16);
      cell_of_ = Kokkos::View<int*, Mem>(alloc_on<ExecSpace>("cell_of"), order.extent(0));
    }
    auto start = cell_start;
    auto fill = fill_;
    auto cell_of = cell_of_;
    auto ord = order;
    // fill(c) is zero here without a clearing pass: zero when allocated, and `place` counts
    // every cell back down to zero.
    Kokkos::parallel_for(
        "cell_sort::count", Policy(0, n), KOKKOS_LAMBDA(const int i) {
          const int c = grid.cell_of(x, i);
          cell_of(i) = c;
          Kokkos::atomic_increment(&fill(c));
        });
    Kokkos::parallel_scan(
        "cell_sort::offsets", Policy(0, ncell),
        KOKKOS_LAMBDA(const int c, int& running, const bool final) {
          const int count = fill(c);
          if (final) start(c) = running;
          running += count;
          if (final && c == ncell - 1) start(ncell) = running;
        });
    // The particle that takes a cell's slot 0 marks itself (cell_of = ~c, negative) as the
    // one that sorts that cell next, so the sort by id visits particles, not the cells:
    // in a dilute gas the cells outnumber the particles several times.
    Kokkos::parallel_for(
        "cell_sort::place", Policy(0, n), KOKKOS_LAMBDA(const int i) {
          const int c = cell_of(i);
          const int slot = Kokkos::atomic_fetch_add(&fill(c), -1) - 1;
          ord(start(c) + slot) = i;
          if (slot == 0) cell_of(i) = ~c;
        });
    // Cells hold a handful of particles: insertion sort by global id is cheap. The order
    // does not depend on the order of `place`'s atomics.
    Kokkos::parallel_for(
        "cell_sort::by_id", Policy(0, n), KOKKOS_LAMBDA(const int i) {
          if (cell_of(i) >= 0) return;
          const int c = ~cell_of(i);
          for (int a = start(c) + 1; a < start(c + 1); ++a) {
            const int p = ord(a);
            const int key = id(p);
            int b = a - 1;
            while (b >= start(c) && id(ord(b)) > key) {
              ord(b + 1) = ord(b);
              --b;
            }
            ord(b + 1) = p;
          }
        });
  }

 private:
  Kokkos::View<int*, Mem> fill_;
  Kokkos::View<int*, Mem> cell_of_;
};

}  // namespace granshock

// The counting sort by cell (kernels/neighbours/cell_sort.hpp): after each sort, cell c
// holds [cell_start(c), cell_start(c + 1)) of `order`, and within a cell the particles go
// by global id, for any thread count. Checked against a host sort by (cell, id) over
// several sorts in a row with crowded cells, because the sort keeps its per-cell counts
// between calls (they must come back to zero) and lets one particle per cell sort it.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <numeric>
#include <vector>

#include "core/domain.hpp"
#include "kernels/device/counter_rng.hpp"
#include "kernels/device/position.hpp"
#include "kernels/neighbours/cell_sort.hpp"

using namespace granshock;

namespace {

using Exec = Kokkos::DefaultExecutionSpace;
using Grid = CellGrid<2, Position>;

struct Sorted {
  std::vector<int> start, order;
};

// The host's answer: indices stably ordered by (cell, id), and each cell's first slot.
Sorted host_sort(const Grid& grid, const std::vector<std::array<double, 2>>& x,
                 const std::vector<int>& id) {
  const int n = int(x.size());
  Kokkos::View<Position* [2], Kokkos::HostSpace> xv("x", n);
  for (int i = 0; i < n; ++i) xv(i, 0) = x[i][0], xv(i, 1) = x[i][1];
  std::vector<int> cell(n);
  for (int i = 0; i < n; ++i) cell[i] = grid.cell_of(xv, i);
  Sorted s;
  s.order.resize(n);
  std::iota(s.order.begin(), s.order.end(), 0);
  std::sort(s.order.begin(), s.order.end(),
            [&](int a, int b) { return cell[a] != cell[b] ? cell[a] < cell[b] : id[a] < id[b]; });
  s.start.assign(grid.total() + 1, 0);
  for (int i = 0; i < n; ++i) ++s.start[cell[i] + 1];
  std::partial_sum(s.start.begin(), s.start.end(), s.start.begin());
  return s;
}

Sorted device_sort(CellSort<2, Position, Exec>& sort, const Grid& grid,
                   const std::vector<std::array<double, 2>>& x, const std::vector<int>& id) {
  const int n = int(x.size());
  Kokkos::View<Position* [2], Exec::memory_space> xv("x", n);
  Kokkos::View<int*, Exec::memory_space> idv("id", n);
  auto xh = Kokkos::create_mirror_view(xv);
  auto idh = Kokkos::create_mirror_view(idv);
  for (int i = 0; i < n; ++i) xh(i, 0) = x[i][0], xh(i, 1) = x[i][1], idh(i) = id[i];
  Kokkos::deep_copy(xv, xh);
  Kokkos::deep_copy(idv, idh);
  sort.sort(grid, xv, idv, n);
  auto start = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sort.cell_start);
  auto order = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sort.order);
  Sorted s;
  s.start.assign(start.data(), start.data() + start.extent(0));
  s.order.assign(order.data(), order.data() + n);
  return s;
}

TEST(CellSort, MatchesHostSortByCellThenIdOverRepeatedSorts) {
  Box box;
  box.hi = {10e-3, 6e-3, 1e-3};
  box.periodic = {true, false, false};
  const Grid grid = Grid::make(box, 1e-3);  // 10 x 6 cells
  CellSort<2, Position, Exec> sort;
  const CounterRng rng{17};
  // Crowded cells (about 8 particles each), then a sparser set with cells left empty,
  // then the first set moved: stale counts of an earlier sort would show in cell_start.
  for (const auto& [n, salt] : {std::pair{480, 0}, std::pair{150, 1}, std::pair{480, 2}}) {
    std::vector<std::array<double, 2>> x(n);
    std::vector<int> id(n);
    for (int i = 0; i < n; ++i) {
      x[i] = {rng.uniform(i, 3 * salt) * 10e-3, rng.uniform(i, 3 * salt + 1) * 6e-3};
      id[i] = int((7919L * i + 13 * salt) % 100003);  // unique, not in index order
    }
    const Sorted want = host_sort(grid, x, id);
    const Sorted got = device_sort(sort, grid, x, id);
    EXPECT_EQ(got.start, want.start) << "sort " << salt;
    EXPECT_EQ(got.order, want.order) << "sort " << salt;
  }
}

}  // namespace

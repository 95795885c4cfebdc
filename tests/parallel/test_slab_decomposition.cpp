// The slab decomposition (parallel/slab_decomposition.hpp): equal and balanced cuts on
// cell-row boundaries, ownership by the cell grid's own arithmetic, neighbours on open and
// periodic axes, and a box too small for the process count refused with a reason.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/user_error.hpp"
#include "kernels/neighbours/cell_grid.hpp"
#include "parallel/slab_decomposition.hpp"

using namespace granshock;

TEST(SlabDecomposition, EqualSlabsCoverEveryRowOnce) {
  const auto s = SlabDecomposition::equal(3, 1, 0.0, 1.0, 10, 2, false);
  ASSERT_EQ(s.ranks(), 3);
  EXPECT_EQ(s.first_row(0), 0);
  EXPECT_EQ(s.end_row(0), 4);  // 10 = 4 + 3 + 3
  EXPECT_EQ(s.end_row(1), 7);
  EXPECT_EQ(s.end_row(2), 10);
  EXPECT_DOUBLE_EQ(s.upper(0), 0.4);
  EXPECT_DOUBLE_EQ(s.lower(2), 0.7);
}

TEST(SlabDecomposition, OwnerFollowsTheCellGridToTheLastBit) {
  // The paper's box along the flow: 0.5 m in 151 rows (not a power of two: inexact rows).
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {0.5, 0.5, 0};
  box.periodic = {true, false, false};
  const auto grid = CellGrid<2, double>::make(box, 0.5 / 151.5);
  ASSERT_EQ(grid.ncell[1], 151);
  const auto s = SlabDecomposition::equal(4, 1, 0.0, 0.5, grid.ncell[1], 1, false);
  // Every row boundary and its neighbouring doubles: the owner is the slab of the grid's row.
  for (int row = 0; row <= 151; ++row) {
    const double at = row * (0.5 / 151);
    for (const double y : {std::nextafter(at, -1.0), at, std::nextafter(at, 1.0)}) {
      const int grid_row = grid.coord(1, y);
      const int owner = s.owner(y);
      EXPECT_GE(grid_row, s.first_row(owner)) << y;
      EXPECT_LT(grid_row, s.end_row(owner)) << y;
    }
  }
  // Outside an open box: the end slabs.
  EXPECT_EQ(s.owner(-0.01), 0);
  EXPECT_EQ(s.owner(0.7), 3);
}

TEST(SlabDecomposition, BalancedCutsEqualiseTheParticleCounts) {
  // A wake: rows 60-99 nearly empty, the rest uniform.
  std::vector<long> count(100, 50);
  for (int r = 60; r < 100; ++r) count[r] = 1;
  const auto s = SlabDecomposition::balanced(4, 1, 0.0, 1.0, count, 3, false);
  const long total = std::accumulate(count.begin(), count.end(), 0L);
  for (int r = 0; r < 4; ++r) {
    const long held =
        std::accumulate(count.begin() + s.first_row(r), count.begin() + s.end_row(r), 0L);
    // Within one row's count (50) of an equal share, except where the minimum width rules.
    if (r < 3) {
      EXPECT_NEAR(double(held), total / 4.0, 50.0) << "rank " << r;
    }
  }
  // Equal slabs would give ranks 0 and 1 1250 particles each and rank 3 25.
  const auto equal = SlabDecomposition::equal(4, 1, 0.0, 1.0, 100, 3, false);
  EXPECT_EQ(equal.first_row(3), 75);
  EXPECT_LT(s.first_row(3), 75);
}

TEST(SlabDecomposition, BalancedRespectsTheMinimumWidth) {
  // Everything in one row: the cuts cannot all sit there.
  std::vector<long> count(20, 0);
  count[10] = 1000;
  const auto s = SlabDecomposition::balanced(3, 1, 0.0, 1.0, count, 4, false);
  for (int r = 0; r < 3; ++r) EXPECT_GE(s.end_row(r) - s.first_row(r), 4) << r;
  EXPECT_EQ(s.end_row(2), 20);
  // The same input gives the same cuts (every rank computes them).
  const auto again = SlabDecomposition::balanced(3, 1, 0.0, 1.0, count, 4, false);
  for (int r = 0; r <= 3; ++r)
    EXPECT_EQ(s.first_row(std::min(r, 2)), again.first_row(std::min(r, 2)));
}

TEST(SlabDecomposition, NeighboursOnOpenAndPeriodicAxes) {
  const auto open = SlabDecomposition::equal(4, 1, 0.0, 1.0, 40, 1, false);
  EXPECT_EQ(open.neighbours(0), std::vector<int>({1}));
  EXPECT_EQ(open.neighbours(2), std::vector<int>({1, 3}));
  const auto periodic = SlabDecomposition::equal(4, 1, 0.0, 1.0, 40, 1, true);
  EXPECT_EQ(periodic.neighbours(0), std::vector<int>({3, 1}));
  const auto two = SlabDecomposition::equal(2, 1, 0.0, 1.0, 40, 1, true);
  EXPECT_EQ(two.neighbours(0), std::vector<int>({1}));  // left and right: the same rank, once
  const auto one = SlabDecomposition::equal(1, 1, 0.0, 1.0, 40, 1, true);
  EXPECT_TRUE(one.neighbours(0).empty());
}

TEST(SlabDecomposition, TooManyProcessesForTheBoxIsAUserError) {
  try {
    SlabDecomposition::equal(8, 1, 0.0, 1.0, 20, 3, false);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("run on at most 6 processes"), std::string::npos)
        << e.what();
  }
  // The message names the axis and its layers: columns across x.
  try {
    SlabDecomposition::equal(3, 0, 0.0, 1.0, 4, 2, true);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("with slabs along x need 6 cell columns (at least 2 per "
                                         "slab, x being periodic), and the box has 4"),
              std::string::npos)
        << e.what();
  }
}

// What the solver's rebalance compares (kernels/particles/slab_exchange.hpp): the heaviest
// slab under the present cuts and under cuts made anew, with the same axis and minimum.
TEST(SlabDecomposition, RebalancedKeepsTheAxisAndLightensTheHeaviestSlab) {
  const auto equal = SlabDecomposition::equal(2, 1, 0.0, 8.0, 8, 2, true);
  const std::vector<long> counts{9, 9, 9, 9, 1, 1, 1, 1};  // the wake: nearly empty rows
  EXPECT_EQ(equal.heaviest(counts), 36);                   // rows 0-3
  const SlabDecomposition moved = equal.rebalanced(counts);
  EXPECT_EQ(moved.first_row(1), 2);  // 18 and 22: the boundary nearest 20
  EXPECT_EQ(moved.heaviest(counts), 22);
  EXPECT_DOUBLE_EQ(moved.lower(1), 2.0);  // the same axis: rows 1 long from 0
  // The minimum of 2 rows (a periodic axis) still holds when the counts pull harder.
  const SlabDecomposition edge = equal.rebalanced({100, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(edge.first_row(1), 2);
}

// Row-owner sampling's bands (kernels/sampling/owner_band.hpp): whatever the particle
// order, the owners' bands tile the rows, so that every bin has exactly one owner and the
// sums have no race; for particles sorted by row, each owner's band starts at the row of
// the first particle of its share, so that its particles are those it advances.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "kernels/sampling/owner_band.hpp"

using namespace granshock;

namespace {

struct Band {
  int lo, hi;
};

std::vector<Band> bands(const std::vector<int>& rows_of_particles, int owners, int rows) {
  std::vector<Band> b(owners);
  const auto row_of = [&](int i) { return rows_of_particles[i]; };
  for (int t = 0; t < owners; ++t)
    owner_band(t, owners, int(rows_of_particles.size()), rows, row_of, b[t].lo, b[t].hi);
  return b;
}

void expect_tiling(const std::vector<Band>& b, int rows) {
  ASSERT_FALSE(b.empty());
  EXPECT_EQ(b.front().lo, 0);
  EXPECT_EQ(b.back().hi, rows);
  for (std::size_t t = 0; t < b.size(); ++t) {
    EXPECT_LE(b[t].lo, b[t].hi) << "owner " << t;
    if (t + 1 < b.size()) {
      EXPECT_EQ(b[t].hi, b[t + 1].lo) << "owner " << t;
    }
  }
}

}  // namespace

TEST(OwnerBand, BandsTileTheRowsWhateverTheOrder) {
  const int rows = 40;
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> any_row(0, rows);  // row_of clamps to [0, rows]
  for (int owners : {1, 2, 3, 5, 16}) {
    for (int n : {0, 1, 3, 17, 1000}) {
      std::vector<int> sorted(n), reversed(n), shuffled(n);
      for (int i = 0; i < n; ++i) sorted[i] = int(long(i) * rows / std::max(n, 1));
      reversed.assign(sorted.rbegin(), sorted.rend());
      for (int& r : shuffled) r = any_row(rng);
      for (const auto* order : {&sorted, &reversed, &shuffled}) {
        SCOPED_TRACE(::testing::Message() << "owners " << owners << ", n " << n);
        expect_tiling(bands(*order, owners, rows), rows);
      }
    }
  }
}

TEST(OwnerBand, SortedParticlesAreOwnedByTheThreadOfTheirShare) {
  // 1000 particles sorted by row, 4 owners: share t is particles [250 t, 250 (t + 1)).
  const int rows = 40, n = 1000, owners = 4;
  std::vector<int> row(n);
  for (int i = 0; i < n; ++i) row[i] = i * rows / n;
  const std::vector<Band> b = bands(row, owners, rows);
  expect_tiling(b, rows);
  for (int t = 0; t < owners; ++t) {
    EXPECT_EQ(b[t].lo, t == 0 ? 0 : row[t * n / owners]);
    for (int i = t * n / owners; i < (t + 1) * n / owners; ++i) {
      EXPECT_GE(row[i], b[t].lo);
      EXPECT_LT(row[i], b[t].hi);
    }
  }
}

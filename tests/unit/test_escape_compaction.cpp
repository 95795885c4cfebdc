// The deletion of escaped particles (kernels/particles/population_kernels.hpp): one scan
// keeps the particles inside in their order and lists the escaped ones at the end of
// `order`, whose faces are then counted. Checked against the host's answer with particles
// leaving through every face in an irregular pattern, none, and all.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <vector>

#include "kernels/device/counter_rng.hpp"
#include "kernels/device/position.hpp"
#include "kernels/particles/population_kernels.hpp"

using namespace granshock;

namespace {

using Exec = Kokkos::DefaultExecutionSpace;
using Mem = Exec::memory_space;

struct Compacted {
  std::vector<int> kept;
  long per_face[4] = {0, 0, 0, 0};
};

// positions: n particles, each inside the unit square or, where `leaves` says, past face
// leaves(i) (0: x < 0, 1: x >= 1, 2: y < 0, 3: y >= 1; -1 inside).
Compacted compact(const std::vector<int>& leaves) {
  const int n = int(leaves.size());
  const CounterRng rng{11};
  Kokkos::View<Position* [2], Mem> x("x", n);
  auto h = Kokkos::create_mirror_view(x);
  for (int i = 0; i < n; ++i) {
    h(i, 0) = 0.1 + 0.8 * rng.uniform(i, 0);
    h(i, 1) = 0.1 + 0.8 * rng.uniform(i, 1);
    if (leaves[i] >= 0) h(i, leaves[i] / 2) = leaves[i] % 2 == 0 ? -0.01 : 1.0;
  }
  Kokkos::deep_copy(x, h);
  EscapeTest<2, Position> test{{0, 0}, {1, 1}, {true, true}};
  Kokkos::View<int*, Mem> order("order", n + 3);  // capacity past n, as the store's
  Compacted c;
  const int kept = compact_escaped<2, Position, Exec>(test, x, n, order, c.per_face);
  auto o = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), order);
  for (int k = 0; k < kept; ++k) c.kept.push_back(o(k));
  return c;
}

void expect_host_answer(const std::vector<int>& leaves) {
  std::vector<int> kept;
  long per_face[4] = {0, 0, 0, 0};
  for (int i = 0; i < int(leaves.size()); ++i) {
    if (leaves[i] < 0)
      kept.push_back(i);
    else
      ++per_face[leaves[i]];
  }
  const Compacted c = compact(leaves);
  EXPECT_EQ(c.kept, kept) << "the kept particles or their order differ";
  for (int f = 0; f < 4; ++f) EXPECT_EQ(c.per_face[f], per_face[f]) << "face " << f;
}

}  // namespace

TEST(EscapeCompaction, KeepsTheOrderAndCountsEveryFace) {
  std::vector<int> leaves(5003, -1);
  const CounterRng rng{5};
  for (int i = 0; i < int(leaves.size()); ++i)
    if (rng.uniform(i, 0) < 0.07) leaves[i] = int(4 * rng.uniform(i, 1));
  leaves.front() = 2;  // the first and the last particle leave too
  leaves.back() = 1;
  expect_host_answer(leaves);
}

TEST(EscapeCompaction, NoneAndAllEscaped) {
  expect_host_answer(std::vector<int>(300, -1));
  std::vector<int> all(300);
  for (int i = 0; i < 300; ++i) all[i] = i % 4;
  expect_host_answer(all);
}

// The cuts of the threads' shares by measured time (core/work_shares.hpp,
// kernels/solver/thread_shares.hpp), against the balanced cuts worked out by hand for
// piecewise-constant costs, and the damped balance converging on a known cost.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <vector>

#include "core/work_shares.hpp"
#include "kernels/device/share.hpp"
#include "kernels/solver/thread_shares.hpp"

using namespace granshock;

TEST(WorkShares, EqualCutsAreTheStaticSchedulesCuts) {
  for (const int items : {0, 1, 61, 1000})
    for (const int shares : {1, 2, 3, 7}) {
      const std::vector<int> cuts = equal_cuts(items, shares);
      ASSERT_EQ(cuts.size(), std::size_t(shares) + 1);
      for (int t = 0; t <= shares; ++t)
        EXPECT_EQ(cuts[std::size_t(t)], share_begin(items, t, shares));
    }
}

TEST(WorkShares, BalancedCutsEqualisePiecewiseConstantCosts) {
  // Two shares of 50 items, the second three times as slow per item: half of the total 4
  // is reached a third of the way into the second share, at 50 + 50/3.
  EXPECT_EQ(balanced_cuts({0, 50, 100}, {1, 3}, 1.0), (std::vector<int>{0, 67, 100}));
  EXPECT_EQ(balanced_cuts({0, 50, 100}, {1, 3}, 0.5), (std::vector<int>{0, 58, 100}));
  // Three shares taking 1, 1 and 4: the thirds of 6 lie at 60 (the end of the second) and
  // halfway into the third (75); each new share then takes 2.
  EXPECT_EQ(balanced_cuts({0, 30, 60, 90}, {1, 1, 4}, 1.0), (std::vector<int>{0, 60, 75, 90}));
  // The reverse: the slow share first.
  EXPECT_EQ(balanced_cuts({0, 50, 100}, {3, 1}, 1.0), (std::vector<int>{0, 33, 100}));
}

TEST(WorkShares, NothingMeasuredOrAnEmptyShareKeepsTheCutsInRange) {
  EXPECT_EQ(balanced_cuts({0, 30, 61}, {0, 0}, 1.0), (std::vector<int>{0, 30, 61}));
  // An empty first share that took some time (the thread's overhead): the cut moves into
  // the second share, never before 0.
  const std::vector<int> cuts = balanced_cuts({0, 0, 100}, {1e-6, 1}, 1.0);
  EXPECT_EQ(cuts.front(), 0);
  EXPECT_EQ(cuts.back(), 100);
  EXPECT_NEAR(cuts[1], 50, 1);
}

TEST(WorkShares, ImbalanceAndRescaledCuts) {
  EXPECT_DOUBLE_EQ(share_imbalance({1, 3}), 1.5);
  EXPECT_DOUBLE_EQ(share_imbalance({2, 2, 2}), 1.0);
  EXPECT_DOUBLE_EQ(share_imbalance({0, 0}), 1.0);
  EXPECT_EQ(rescaled_cuts({0, 30, 61}, 122), (std::vector<int>{0, 60, 122}));
  EXPECT_EQ(rescaled_cuts({0, 0, 0}, 10), (std::vector<int>{0, 5, 10}));
}

// The damped balance on a range whose items cost 1 below 50 and 3 from 50 on (total 200):
// the cut that gives each of two threads 100 lies at 50 + 50/3. Half steps converge on
// it from equal shares, to within one item, and then stay (within the tolerated
// imbalance nothing moves).
TEST(ThreadShares, DampedBalanceConvergesOnTheCostsCut) {
  ThreadShares<Kokkos::HostSpace> shares;
  const auto cost = [](int from, int to) {
    double c = 0;
    for (int i = from; i < to; ++i) c += i < 50 ? 1 : 3;
    return c;
  };
  for (int region = 0; region < 12; ++region) {
    const auto cuts = shares.cuts(100, 2);
    shares.seconds()(0) = cost(cuts(0), cuts(1));
    shares.seconds()(1) = cost(cuts(1), cuts(2));
    shares.balance(ThreadShares<Kokkos::HostSpace>::least_steps);
  }
  EXPECT_NEAR(shares.current()[1], 50 + 50.0 / 3, 1.0);
  EXPECT_GT(shares.stats().moves, 2);
  EXPECT_LT(shares.stats().imbalance, ThreadShares<Kokkos::HostSpace>::tolerated_imbalance);
  ASSERT_EQ(shares.stats().shares.size(), 2u);
  EXPECT_NEAR(shares.stats().shares[0], 0.67, 0.02);
  // A region too short to measure leaves the cuts.
  const std::vector<int> before = shares.current();
  shares.seconds()(0) = 1;
  shares.seconds()(1) = 100;
  shares.balance(ThreadShares<Kokkos::HostSpace>::least_steps - 1);
  EXPECT_EQ(shares.current(), before);
}

// Equal mode ignores the times; a count that changes rescales kept cuts.
TEST(ThreadShares, EqualModeAndAChangedCount) {
  ThreadShares<Kokkos::HostSpace> equal(ThreadShareMode::equal);
  equal.cuts(100, 2);
  equal.seconds()(0) = 1;
  equal.seconds()(1) = 3;
  equal.balance(100);
  EXPECT_EQ(equal.cuts(100, 2)(1), 50);
  ThreadShares<Kokkos::HostSpace> timed;
  timed.cuts(100, 2);
  timed.seconds()(0) = 1;
  timed.seconds()(1) = 3;
  timed.balance(100);
  EXPECT_EQ(timed.current()[1], 58);
  EXPECT_EQ(timed.cuts(200, 2)(1), 116);
}

// The counter-based generator: reproducible, independent of call order, and with the
// moments of its distributions (tolerances: 5 standard errors of the sample mean).
#include <gtest/gtest.h>

#include <cmath>

#include "kernels/device/counter_rng.hpp"

using granshock::CounterRng;

TEST(CounterRng, SameCounterSameValueAnyOrder) {
  const CounterRng a{42}, b{42};
  std::vector<std::uint64_t> forward, backward(100);
  for (int k = 0; k < 100; ++k) forward.push_back(a.bits(7, k));
  for (int k = 99; k >= 0; --k) backward[k] = b.bits(7, k);
  EXPECT_EQ(forward, backward);
}

TEST(CounterRng, SeedsAndStreamsDiffer) {
  const CounterRng a{1}, b{2};
  int equal_seed = 0, equal_stream = 0;
  for (int k = 0; k < 1000; ++k) {
    equal_seed += a.bits(0, k) == b.bits(0, k);
    equal_stream += a.bits(0, k) == a.bits(1, k);
  }
  EXPECT_EQ(equal_seed, 0);
  EXPECT_EQ(equal_stream, 0);
}

TEST(CounterRng, UniformAndNormalMoments) {
  const CounterRng rng{2024};
  const int n = 200000;
  double su = 0, su2 = 0, sn = 0, sn2 = 0, sn4 = 0;
  for (int k = 0; k < n; ++k) {
    const double u = rng.uniform(3, k);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    su += u;
    su2 += u * u;
    const double z = rng.normal(4, k);
    sn += z;
    sn2 += z * z;
    sn4 += z * z * z * z;
  }
  // Uniform: mean 1/2 (sd 0.2887), E[u^2] = 1/3 (sd 0.298). Normal: mean 0 (sd 1),
  // E[z^2] = 1 (sd sqrt 2), E[z^4] = 3 (sd sqrt 96).
  const double se = 1.0 / std::sqrt(double(n));
  EXPECT_NEAR(su / n, 0.5, 5 * 0.2887 * se);
  EXPECT_NEAR(su2 / n, 1.0 / 3.0, 5 * 0.298 * se);
  EXPECT_NEAR(sn / n, 0.0, 5 * se);
  EXPECT_NEAR(sn2 / n, 1.0, 5 * std::sqrt(2.0) * se);
  EXPECT_NEAR(sn4 / n, 3.0, 5 * std::sqrt(96.0) * se);
}

// The minimum image of the pair loop (kernels/device/box_geometry.hpp): on a periodic axis
// nearby_image takes the nearest image, bitwise as minimum_image does; on an open axis it
// leaves the displacement as it is, and its comparisons there are never true (they were
// for every other pair, a branch mispredicted at half the pairs of the paper case's open
// axis: docs/benchmarks.md, "The paper case against the gas at the same N").
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "kernels/device/box_geometry.hpp"

using namespace granshock;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

BoxGeometry<2, double> periodic_in_x() {
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {0.5, 0.3, 1};
  box.periodic = {true, false, false};
  return BoxGeometry<2, double>::from(box);
}

}  // namespace

TEST(BoxGeometry, AnOpenAxisKeepsEveryDisplacementAndNeverCompares) {
  const BoxGeometry<2, double> g = periodic_in_x();
  EXPECT_EQ(g.half_image[1], std::numeric_limits<double>::max());
  EXPECT_EQ(g.image_length[1], 0.0);
  for (const double dy : {0.0, -0.0, 1e-3, -1e-3, 0.2, -0.2, 0.29, -0.29, 1e300, -1e300}) {
    const Vec<2, double> out = g.nearby_image(Vec<2, double>{{0.0, dy}});
    EXPECT_TRUE(same_bits(out[1], dy)) << dy;
  }
}

TEST(BoxGeometry, APeriodicAxisTakesTheNearestImageAsMinimumImageDoes) {
  const BoxGeometry<2, double> g = periodic_in_x();
  EXPECT_EQ(g.half_image[0], 0.25);
  EXPECT_EQ(g.nearby_image(Vec<2, double>{{0.3, 0.0}})[0], 0.3 - 0.5);
  EXPECT_EQ(g.nearby_image(Vec<2, double>{{-0.3, 0.0}})[0], -0.3 + 0.5);
  EXPECT_EQ(g.nearby_image(Vec<2, double>{{0.2, 0.0}})[0], 0.2);
  // Partners closer than half the box on either side of the seam, as in a list: the same
  // bits as the rounding of minimum_image.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(0.0, 0.5), offset(-0.2, 0.2);
  for (int k = 0; k < 10000; ++k) {
    const double xi = x(rng), xj = std::fmod(xi + offset(rng) + 0.5, 0.5);
    const Vec<2, double> dx{{xi - xj, 0.01}};
    EXPECT_TRUE(same_bits(g.nearby_image(dx)[0], g.minimum_image(dx)[0])) << xi << " " << xj;
  }
}

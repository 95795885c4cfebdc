// docs/fields.md: the shock front and the detachment length of
// a synthetic phi field with a known step are found within one bin, the far-field angle of
// a straight oblique front is recovered, and the uncertainty of delta from block averages
// shrinks as blocks are added.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/bin_fields.hpp"
#include "analysis/detachment.hpp"
#include "analysis/front_crossing.hpp"
#include "analysis/shock_front.hpp"
#include "synthetic_run.hpp"

using namespace granshock;

namespace {

constexpr double kD = 1e-3;  // particle diameter
// The scene's cylinder: D = 12 d at (30 d, 60 d), surface at y = 54 d on the axis.
constexpr double kXc = 30 * kD, kSurface = 54 * kD;  // obstacle axis, cylinder surface
// A V-shaped front: apex 6.3 d ahead of the surface, flanks at beta = 50 deg to +y.
constexpr double kApex = kSurface - 6.3 * kD;
const double kCotBeta = 1.0 / std::tan(50.0 * M_PI / 180.0);

double front_y(double x, double shift = 0) {
  return kApex + shift + std::abs(x - kXc) * kCotBeta;
}

const FieldPhysics& physics() {
  static const FieldPhysics phys = test::physics_of(test::bow_shock_scene(12));
  return phys;
}

// Upstream: phi 0.1 at Ma 6; behind the front: phi 0.4, slow and hot.
test::BinState pre() {
  const FieldPhysics& p = physics();
  return test::mixture_state(p, 0.1, test::temperature_for_mach(p, 0.1, 1.0, 6.0), 0, 1.0);
}
test::BinState post() {
  const FieldPhysics& p = physics();
  return test::mixture_state(p, 0.4, test::temperature_for_mach(p, 0.4, 0.2, 0.5), 0, 0.2);
}

// The stagnation-line profile: x in [xc - 1.5 d, xc + 1.5 d], bins of 0.5 d from y = 0,
// with the front of block b at front_y + shifts[b].
BinSums profile_with_shifts(const std::vector<double>& shifts) {
  BinSums s = test::empty_sums(1, 180, static_cast<int>(shifts.size()), kXc - 1.5 * kD, 0, 3 * kD,
                               0.5 * kD);
  test::fill_with_front(
      s, physics(), pre(), post(),
      [&](double x, double y, int b) {
        return y > front_y(x, shifts[static_cast<std::size_t>(b)]);
      },
      200);
  return s;
}

}  // namespace

TEST(ShockFront, StepFieldFoundWithinOneBinAndFarFieldAngle) {
  const FieldPhysics& phys = physics();
  BinSums grid = test::empty_sums(20, 30, 1, 0, 0, 3 * kD, 3 * kD);
  test::fill_with_front(
      grid, phys, pre(), post(), [](double x, double y, int) { return y > front_y(x); }, 300);
  const BinFields f = compute_bin_fields(grid, phys);
  const ShockFront front = find_shock_front(f, grid, phys, 0.1, 2);
  int columns = 0;
  for (int ix = 0; ix < grid.nx; ++ix) {
    const double x = grid.x_centre(ix), expected = front_y(x);
    if (expected > grid.y0 + grid.ny * grid.dy - 2 * grid.dy) continue;  // front leaves the domain
    ++columns;
    ASSERT_TRUE(std::isfinite(front.y_threshold[static_cast<std::size_t>(ix)])) << "column " << ix;
    EXPECT_NEAR(front.y_threshold[static_cast<std::size_t>(ix)], expected, grid.dy)
        << "column " << ix;
    EXPECT_NEAR(front.y_max_gradient[static_cast<std::size_t>(ix)], expected, grid.dy)
        << "column " << ix;
    // The T front of the same step (the primary definition's, which the figures draw). The
    // bin the step crosses holds both flows, and their different mean speeds make its T
    // the column's largest, so the half-rise lies between that bin's centre (within half a
    // bin of the step) and the centre before it: 1.5 bins upstream of the step at most.
    const double y_hot = front.y_temperature[static_cast<std::size_t>(ix)];
    EXPECT_GE(y_hot, expected - 1.5 * grid.dy) << "column " << ix;
    EXPECT_LE(y_hot, expected + grid.dy) << "column " << ix;
    // Beside the cylinder the peak is the post-shock phi; in front of it, the last bins
    // searched are cut by the cylinder's surface and hold less.
    if (std::abs(x - kXc) > 6 * kD) {
      EXPECT_NEAR(front.phi_peak[static_cast<std::size_t>(ix)], 0.4, 1e-9) << "column " << ix;
    }
  }
  EXPECT_GE(columns, 18);
  ASSERT_FALSE(front.threshold_lines.empty());
  // Far field: |x - xc| in [D, W/2 - 2 bins] = [12 d, 24 d]: 4 columns per flank.
  EXPECT_GE(front.left.points, 3);
  EXPECT_GE(front.right.points, 3);
  EXPECT_NEAR(front.left.angle_deg, 50.0, 2.0);
  EXPECT_NEAR(front.right.angle_deg, 50.0, 2.0);
  EXPECT_NEAR(front.angle_deg, 50.0, 2.0);
}

// A free stream whose T doubles at y = 45 d without any compression (phi stays 0.1), as the
// inflow of a short run, cooled by its own collisions, meets warmer gas: the largest rise
// of T alone would call it a front (2 >= 1.5-fold); without a rise of phi no column has a
// front of either kind, and nothing is drawn.
TEST(ShockFront, TemperatureRiseWithoutCompressionIsNoFront) {
  const FieldPhysics& phys = physics();
  test::BinState warm = pre();
  for (double& t : warm.temperature) t *= 2;
  BinSums grid = test::empty_sums(20, 30, 1, 0, 0, 3 * kD, 3 * kD);
  test::fill_with_front(
      grid, phys, pre(), warm, [](double, double y, int) { return y > 45 * kD; }, 300);
  const BinFields f = compute_bin_fields(grid, phys);
  const ShockFront front = find_shock_front(f, grid, phys, 0.1, 2);
  int warm_columns = 0;
  for (int ix = 0; ix < grid.nx; ++ix) {
    const std::size_t i = static_cast<std::size_t>(ix);
    EXPECT_TRUE(std::isnan(front.y_threshold[i])) << "column " << ix;
    EXPECT_TRUE(std::isnan(front.y_temperature[i])) << "column " << ix;
    // The negative control: the temperature alone has a rise the rule would take.
    std::vector<double> t(static_cast<std::size_t>(grid.ny)), y(t.size());
    for (int iy = 0; iy < grid.ny; ++iy) {
      const std::size_t k = f.index(iy, ix);
      t[static_cast<std::size_t>(iy)] = f.masked[k] ? NAN : f.temperature[k];
      y[static_cast<std::size_t>(iy)] = grid.y_centre(iy);
    }
    const int end = grid.ny;  // columns beside the cylinder search every row
    if (std::abs(grid.x_centre(ix) - kXc) > 9 * kD &&
        find_largest_rise(t, y, 2, end, ThresholdRule{}).found)
      ++warm_columns;
  }
  EXPECT_GE(warm_columns, 10);
  EXPECT_TRUE(front.temperature_lines.empty());
}

TEST(Detachment, StepProfileFoundWithinOneBin) {
  const BinSums profile = profile_with_shifts({0.0});
  const Detachment d = measure_detachment(profile, physics(), 0.1, 5 * kD);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.surface, kSurface, 1e-12);
  // The strip is 3 d wide, so the front inside it spans |x - xc| <= 1.5 d: its bins see
  // the front smeared over 1.5 d cot(beta) = 1.26 d; the threshold rule lands within it.
  const double expected = kSurface - kApex;
  EXPECT_NEAR(d.delta, expected, profile.dy + 1.5 * kD * kCotBeta)
      << "delta = " << d.delta / kD << " d";
  EXPECT_NEAR(d.delta_over_d, d.delta / (12 * kD), 1e-12);
  EXPECT_TRUE(std::isnan(d.delta_err)) << "one block has no spread to measure";
}

TEST(Detachment, StepProfileOnTheAxisFoundWithinOneBin) {
  // A plane front across the strip (no smearing): delta within one profile bin.
  BinSums s = test::empty_sums(1, 180, 1, kXc - 1.5 * kD, 0, 3 * kD, 0.5 * kD);
  test::fill_with_front(
      s, physics(), pre(), post(), [](double, double y, int) { return y > kApex; }, 200);
  const Detachment d = measure_detachment(s, physics(), 0.1, 5 * kD);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.delta, kSurface - kApex, s.dy);
}

TEST(Detachment, UncertaintyShrinksAsBlocksAreAdded) {
  // Each block's front is displaced by a "noise" of standard deviation 1 d: the quantiles
  // of a normal distribution at (k + 1/2)/B in a scrambled order (deterministic).
  auto shifts = [](int blocks) {
    std::vector<double> s;
    for (int k = 0; k < blocks; ++k) {
      const double p = (k + 0.5) / blocks;
      // Inverse normal CDF by bisection on erf.
      double lo = -6, hi = 6;
      for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
      }
      s.push_back(0.5 * (lo + hi) * kD);
    }
    for (std::size_t i = 0; i < s.size(); ++i) std::swap(s[i], s[(7 * i + 3) % s.size()]);
    return s;
  };
  const std::vector<double> s4 = shifts(4), s16 = shifts(16);
  const Detachment d4 = measure_detachment(profile_with_shifts(s4), physics(), 0.1, 5 * kD);
  const Detachment d16 = measure_detachment(profile_with_shifts(s16), physics(), 0.1, 5 * kD);
  ASSERT_TRUE(d4.found);
  ASSERT_TRUE(d16.found);
  EXPECT_EQ(d4.blocks_used, 4);
  EXPECT_EQ(d16.blocks_used, 16);
  // Each block's delta follows its own front (within one bin plus the strip's smearing).
  for (std::size_t b = 0; b < s16.size(); ++b)
    EXPECT_NEAR(d16.delta_blocks[b], kSurface - kApex - s16[b], 0.5 * kD + 1.5 * kD * kCotBeta)
        << "block " << b;
  // The standard error is about sigma / sqrt(B) (sigma = 1 d): halves from 4 to 16 blocks.
  EXPECT_GT(d4.delta_err, 0.0);
  EXPECT_LT(d16.delta_err, 0.7 * d4.delta_err)
      << d16.delta_err / kD << " d vs " << d4.delta_err / kD << " d";
  EXPECT_NEAR(d4.delta_err / kD, 1.0 / 2.0, 0.25);
  EXPECT_NEAR(d16.delta_err / kD, 1.0 / 4.0, 0.12);
  EXPECT_NEAR(d16.delta_over_d_err, d16.delta_err / (12 * kD), 1e-15);
}

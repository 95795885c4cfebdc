// Whether a production window is steady (docs/fields.md, section 12), on synthetic time
// series: a steady series with noise is not flagged, a ramp is, and a window that starts
// before the gas that met the obstacle at t = 0 has left the domain is flagged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "analysis/steadiness.hpp"
#include "synthetic_run.hpp"

using namespace granshock;

namespace {

// 101 rows from t0 to t1 of mean + slope (t - t0) + noise: a fixed pseudo-random sequence
// of unit variance (uniform on [-sqrt 3, sqrt 3]).
std::vector<double> series(const std::vector<double>& t, double mean, double slope, double noise) {
  std::vector<double> x;
  unsigned state = 12345;
  for (double ti : t) {
    state = state * 1103515245u + 12345u;
    const double u = ((state >> 8) & 0xffff) / 65535.0;  // [0, 1]
    x.push_back(mean + slope * (ti - t.front()) + noise * std::sqrt(3.0) * (2 * u - 1));
  }
  return x;
}

std::vector<double> times(double t0, double t1, int rows) {
  std::vector<double> t;
  for (int i = 0; i < rows; ++i) t.push_back(t0 + (t1 - t0) * i / (rows - 1));
  return t;
}

// The synthetic scene: 90 d long, cylinder face at 54 d, U = 1 m/s: the gas at the face
// leaves after 36 d / U = 0.036 s, L/U = 0.09 s.
const FieldPhysics& physics() {
  static const FieldPhysics phys = test::physics_of(test::bow_shock_scene());
  return phys;
}

}  // namespace

TEST(Steadiness, ASteadySeriesWithNoiseIsNotFlagged) {
  const std::vector<double> t = times(0.1, 0.3, 101);
  const HalvesTrend h = halves_trend(t, series(t, 3770, 0, 5), 0.1, 0.3);
  ASSERT_TRUE(h.determined);
  EXPECT_EQ(h.rows, 101);
  EXPECT_TRUE(h.steady) << h.drift_over_scatter;
  EXPECT_LT(std::abs(h.drift_over_scatter), 1.0);
  EXPECT_NEAR(h.scatter, 5, 1);
}

TEST(Steadiness, ARampIsFlagged) {
  const std::vector<double> t = times(0.1, 0.3, 101);
  // A drift of 10 units over the window against noise of 1: flagged, with its sign.
  const HalvesTrend h = halves_trend(t, series(t, 3770, 10 / 0.2, 1), 0.1, 0.3);
  ASSERT_TRUE(h.determined);
  EXPECT_FALSE(h.steady);
  EXPECT_GT(h.drift_over_scatter, 2.0);
  EXPECT_NEAR(h.relative_drift, 5.0 / 3770, 0.5 / 3770);
  // A noiseless ramp: sqrt(12) times its scatter, whatever its size.
  const HalvesTrend pure = halves_trend(t, series(t, 1, -1e-3, 0), 0.1, 0.3);
  EXPECT_FALSE(pure.steady);
  EXPECT_NEAR(pure.drift_over_scatter, -std::sqrt(12.0), 0.1);
  // Rows outside the window do not count: the ramp before 0.1 s is left out.
  std::vector<double> t_long = times(0.0, 0.3, 151), x_long = series(t_long, 3770, 0, 1);
  for (std::size_t i = 0; i < t_long.size(); ++i)
    if (t_long[i] < 0.1) x_long[i] += 1000 * (0.1 - t_long[i]);
  const HalvesTrend windowed = halves_trend(t_long, x_long, 0.1, 0.3);
  EXPECT_EQ(windowed.rows, 101);
  EXPECT_TRUE(windowed.steady) << windowed.drift_over_scatter;
}

TEST(Steadiness, TooFewRowsGiveNoVerdict) {
  const std::vector<double> t = times(0.1, 0.3, 6);  // 3 rows a half
  const HalvesTrend h = halves_trend(t, series(t, 1, 1, 0), 0.1, 0.3);
  EXPECT_FALSE(h.determined);
  EXPECT_TRUE(h.steady);
  EXPECT_NE(h.reason.find("3 and 3 time-series rows"), std::string::npos) << h.reason;
}

TEST(Steadiness, TheRunIsFlaggedByAnyCheckAndSaysWhich) {
  const FieldPhysics& phys = physics();
  ASSERT_TRUE(phys.obstacle.has_value());
  const DetachmentConvergence none;  // no halves: the front check has no verdict
  RunSeries steady;
  steady.time = times(0.05, 0.1, 51);
  steady.particles = series(steady.time, 1000, 0, 3);
  steady.kinetic_energy = series(steady.time, 2e-3, 0, 1e-5);
  const Steadiness ok = assess_steadiness(steady, 0.05, 0.1, phys, none);
  EXPECT_NEAR(ok.flow_through_time, 0.09, 1e-12);
  EXPECT_NEAR(ok.washout_time, 0.036, 1e-12);
  EXPECT_TRUE(ok.steady) << ok.warning;
  EXPECT_TRUE(ok.warning.empty());
  EXPECT_FALSE(ok.front.determined);

  // The same series in a window that starts at 0.02 s, before the washout.
  RunSeries early = steady;
  for (double& t : early.time) t -= 0.03;
  const Steadiness too_early = assess_steadiness(early, 0.02, 0.07, phys, none);
  EXPECT_FALSE(too_early.steady);
  EXPECT_FALSE(too_early.start_after_washout);
  EXPECT_EQ(too_early.warning.rfind("not yet steady: the window starts at 0.02 s", 0), 0u)
      << too_early.warning;

  // The kinetic energy falling through the window (as the default scene's does before
  // 0.07 s): flagged, and the warning names it.
  RunSeries cooling = steady;
  cooling.kinetic_energy = series(cooling.time, 2e-3, -2e-3, 1e-5);
  const Steadiness falling = assess_steadiness(cooling, 0.05, 0.1, phys, none);
  EXPECT_FALSE(falling.steady);
  EXPECT_TRUE(falling.particles.steady);
  EXPECT_FALSE(falling.kinetic_energy.steady);
  EXPECT_NE(falling.warning.find("the kinetic energy drifts by -"), std::string::npos)
      << falling.warning;
}

TEST(Steadiness, TheFrontMovingBetweenTheHalvesIsFlagged) {
  const double D = 12e-3;
  auto halves = [D](double first, double second, double err) {
    DetachmentConvergence c;
    for (const char* label : {"first half of the window", "second half of the window"}) {
      ConvergenceChoice choice;
      choice.kind = "window";
      choice.label = label;
      for (std::size_t k = 0; k < kFrontDefinitions.size(); ++k) {
        Detachment& d = choice.result[k];
        d.definition = kFrontDefinitions[k];
        d.found = d.definition == kPrimaryFront;  // the others must not count
        d.delta = (c.choices.empty() ? first : second) * D;
        d.delta_err = err * D;
        if (!d.found) d.delta = 10 * D;
      }
      c.choices.push_back(choice);
    }
    return c;
  };
  const FrontHalves same = front_halves(halves(0.25, 0.26, 0.01), D);
  ASSERT_TRUE(same.determined) << same.reason;
  EXPECT_TRUE(same.steady);
  EXPECT_NEAR(same.shift_over_error, 0.01 / std::sqrt(2 * 0.01 * 0.01), 1e-9);
  const FrontHalves moved = front_halves(halves(0.25, 0.35, 0.01), D);
  ASSERT_TRUE(moved.determined);
  EXPECT_FALSE(moved.steady);
  EXPECT_NEAR(moved.first_over_D, 0.25, 1e-12);
  EXPECT_NEAR(moved.second_over_D, 0.35, 1e-12);
  const FrontHalves no_errors =
      front_halves(halves(0.25, 0.35, std::numeric_limits<double>::quiet_NaN()), D);
  EXPECT_FALSE(no_errors.determined);
  EXPECT_TRUE(no_errors.steady);
}

// The skin test's speed bound (kernels/neighbours/rebuild_watch.hpp): whenever it says the
// Verlet list is still valid, no particle may have moved skin/2, and the solver must
// rebuild at the same steps, with bitwise the same trajectory, as when it measures every
// particle's displacement every step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "kernels/neighbours/rebuild_watch.hpp"
#include "same_particles.hpp"

using namespace granshock;

TEST(RebuildWatch, BoundGrowsByTheTopSpeedOfEachDrift) {
  const double dt = 1e-6, limit = 1e-4;
  RebuildWatch watch(limit, dt);
  EXPECT_TRUE(watch.exact_known());
  watch.drifted(4.0);  // 2 m/s: 2e-6 m per step
  EXPECT_FALSE(watch.exact_known());
  // 49 steps move at most 9.8e-5 m < 1e-4 m; the 50th reaches the limit, where only an
  // exact measurement can tell.
  for (int k = 1; k < 49; ++k) watch.drifted(4.0);
  EXPECT_TRUE(watch.bound_proves_valid());
  watch.drifted(4.0);
  EXPECT_FALSE(watch.bound_proves_valid());
  // An exact measurement replaces the bound: the particles turned round.
  watch.measured(1e-10);  // 1e-5 m
  EXPECT_TRUE(watch.exact_known());
  EXPECT_DOUBLE_EQ(watch.exact_d2(), 1e-10);
  EXPECT_TRUE(watch.bound_proves_valid());
  watch.rebuilt();
  EXPECT_EQ(watch.exact_d2(), 0.0);
}

TEST(RebuildWatch, DriftsAreMeasuredExactlyNearTheLimit) {
  const double dt = 1e-6, limit = 1e-4;
  RebuildWatch watch(limit, dt);
  watch.drifted(1.0);  // 1e-6 m per step, lookahead 16 steps
  EXPECT_TRUE(watch.next_drift_by_speed());
  watch.measured(std::pow(limit - 10 * dt * 1.0, 2));
  EXPECT_FALSE(watch.next_drift_by_speed());
}

// An independent check of the bound: random walkers with speeds that change every step,
// their displacements accumulated exactly as the solver does (double positions); every
// time the watch says "valid" without a measurement, every walker must be below the limit.
TEST(RebuildWatch, NeverProvesValidPastTheLimit) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> kick(0.0, 0.3);
  const double dt = 5e-7, limit = 1.5e-4;
  const int walkers = 200;
  std::vector<double> x(walkers), y(walkers), vx(walkers), vy(walkers);
  for (int i = 0; i < walkers; ++i) vx[i] = kick(rng), vy[i] = kick(rng);
  RebuildWatch watch(limit, dt);
  int proved = 0, steps_past_limit = 0;
  for (int step = 0; step < 20000; ++step) {
    double top_v2 = 0, top_d2 = 0;
    for (int i = 0; i < walkers; ++i) {
      vx[i] += 0.05 * kick(rng);
      vy[i] += 0.05 * kick(rng);
      x[i] += dt * vx[i];
      y[i] += dt * vy[i];
      top_v2 = std::max(top_v2, vx[i] * vx[i] + vy[i] * vy[i]);
      top_d2 = std::max(top_d2, x[i] * x[i] + y[i] * y[i]);
    }
    watch.drifted(top_v2);
    if (watch.bound_proves_valid()) {
      ++proved;
      ASSERT_LT(top_d2, limit * limit) << "step " << step;
    } else {
      watch.measured(top_d2);
      if (top_d2 > limit * limit) {  // rebuild: every walker starts again from 0
        ++steps_past_limit;
        std::fill(x.begin(), x.end(), 0.0);
        std::fill(y.begin(), y.end(), 0.0);
        watch.rebuilt();
      }
    }
  }
  EXPECT_GT(steps_past_limit, 10);  // the walk crossed the limit often
  EXPECT_GT(proved, 10000);         // and the bound spared most measurements
}

namespace {

using test::expect_bitwise_identical;

// The same gas advanced with the bound and with an exact measurement every step.
void compare_with_exact_check(SolverSetup s, double phi, int steps) {
  GasSpec spec;
  spec.particles = 2000;
  spec.area_fraction = phi;
  spec.sigma_m_per_s = 2.0;
  size_periodic_box(s, spec);
  const HostParticles gas = make_homogeneous_gas(s, spec);
  SolverSetup exact_setup = s;
  exact_setup.exact_list_check = true;
  auto bounded = make_solver(s, gas.size(), Backend::default_space);
  auto exact = make_solver(exact_setup, gas.size(), Backend::default_space);
  bounded->set_particles(gas);
  exact->set_particles(gas);
  for (int chunk = 0; chunk < 4; ++chunk) {  // several advance() calls, as a run makes
    bounded->advance(steps / 4);
    exact->advance(steps / 4);
  }
  EXPECT_GT(exact->list_builds(), 3);
  EXPECT_EQ(bounded->list_builds(), exact->list_builds());
  EXPECT_EQ(exact->exact_list_checks(), 0);
  EXPECT_GT(bounded->diagnostics().contacts, 0);
  expect_bitwise_identical(bounded->particles(), exact->particles());
}

}  // namespace

TEST(RebuildWatch, SameTrajectoryAsMeasuringEveryStepDiluteGas) {
  SolverSetup s = paper_mixture(0.5);
  s.dt = 5e-8;
  compare_with_exact_check(s, 0.1, 4000);
}

TEST(RebuildWatch, SameTrajectoryAsMeasuringEveryStepDenseGasSinglePrecision) {
  SolverSetup s = paper_mixture(0.9);
  s.precision = Precision::single_precision;
  s.dt = 5e-8;
  compare_with_exact_check(s, 0.6, 4000);
}

TEST(RebuildWatch, SameTrajectoryAsMeasuringEveryStepWithFriction) {
  SolverSetup s = paper_mixture(0.5);
  s.contacts = ContactSettings::uniform(2, 0.5, 0.4);
  s.dt = 3e-8;
  compare_with_exact_check(s, 0.5, 4000);
}

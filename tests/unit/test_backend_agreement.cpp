// docs/design.md: the OpenMP backend with 2 threads and the Serial
// backend give bitwise identical trajectories; and the fused step gives those of the
// separate velocity-Verlet halves. Why bitwise is possible: every particle
// sums its own forces over a full neighbour list in a fixed order (no atomics), cells
// are ordered by global id after the counting sort, and the only reduction that steers
// the run (the largest displacement) is a max, which is exact in any order.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "kernels/device/backends.hpp"
#include "models/obstacle_shapes.hpp"
#include "same_particles.hpp"
#include "solver_on_paths.hpp"

using namespace granshock;

namespace {

using test::expect_bitwise_identical;

// A 2500-particle gas at phi = 0.4 in a periodic box (around a centred cylinder when the
// setup has one, the box then open along z in 2-D); in 3-D (s.dim = 3) a cube of
// 14^3 = 2744 spheres, periodic on every axis, around the cylinder extruded along z.
HostParticles make_gas(SolverSetup& s) {
  GasSpec spec;
  spec.particles = 2500;
  spec.area_fraction = 0.4;
  spec.sigma_m_per_s = 2.0;
  size_periodic_box(s, spec);
  if (s.obstacle) {
    s.obstacle->centre = {0.5 * s.box.length(0), 0.5 * s.box.length(1), 0};
    s.box.periodic = {true, true, s.dim == 3};
  }
  HostParticles gas = make_homogeneous_gas(s, spec);
  if (s.obstacle) {  // remove particles that would start inside the cylinder
    HostParticles kept;
    for (std::size_t i = 0; i < gas.size(); ++i) {
      const double dx = gas.position[i][0] - s.obstacle->centre[0];
      const double dy = gas.position[i][1] - s.obstacle->centre[1];
      if (std::hypot(dx, dy) > 0.5 * CylinderShape::diameter(*s.obstacle) + 1e-3)
        kept.add(gas.position[i], gas.velocity[i], gas.species[i], gas.id[i]);
    }
    gas = kept;
  }
  return gas;
}

// The default backend against Serial: a GPU (Cuda in a CUDA build), or a host backend of
// several threads. Either way the solvers hand their particles over as host copies.
void compare_backends(SolverSetup s, int steps) {
  // A Kokkos without Serial beside its default backend (or a build with
  // GRANSHOCK_SERIAL_VARIANTS=OFF) has nothing to compare: Backend::serial is the default.
  if constexpr (!GRANSHOCK_SEPARATE_SERIAL)
    GTEST_SKIP() << "needs Serial beside the default backend (this Kokkos or build has none)";
  if (Kokkos::DefaultExecutionSpace().concurrency() < 2)
    GTEST_SKIP() << "needs a default backend other than Serial: a GPU, or OpenMP with 2 or "
                    "more threads (OMP_NUM_THREADS=2)";
  const HostParticles gas = make_gas(s);
  auto parallel = make_solver(s, gas.size(), Backend::default_space);
  auto serial = make_solver(s, gas.size(), Backend::serial);
  ASSERT_NE(parallel->variant(), serial->variant());
  parallel->set_particles(gas);
  serial->set_particles(gas);
  parallel->advance(steps);
  serial->advance(steps);
  EXPECT_GT(parallel->list_builds(), 1);
  EXPECT_GT(parallel->diagnostics().contacts + serial->diagnostics().contacts, 0);
  expect_bitwise_identical(parallel->particles(), serial->particles());
}

// advance(n) fuses the second half of each step with the first half of the next
// (kernels/solver/fused_step.hpp); n calls of advance(1) run the halves separately. The
// two must give bitwise the same trajectory, spins, springs and obstacle included.
void compare_fused_with_separate_halves(SolverSetup s, int steps) {
  const HostParticles gas = make_gas(s);
  auto fused = make_solver(s, gas.size(), Backend::default_space);
  auto separate = make_solver(s, gas.size(), Backend::default_space);
  fused->set_particles(gas);
  separate->set_particles(gas);
  fused->advance(steps);
  for (int k = 0; k < steps; ++k) separate->advance(1);
  EXPECT_EQ(fused->steps_done(), separate->steps_done());
  EXPECT_EQ(fused->list_builds(), separate->list_builds());
  EXPECT_GT(fused->list_builds(), 1);
  EXPECT_GT(fused->diagnostics().contacts, 0);
  expect_bitwise_identical(fused->particles(), separate->particles());
  // The next steps start from the forces advance() left: they must agree as well.
  fused->advance(50);
  separate->advance(50);
  expect_bitwise_identical(fused->particles(), separate->particles());
}

// The scenes both comparisons run: frictionless, and friction with the cylinder.
SolverSetup frictionless() {
  SolverSetup s = paper_mixture(0.5);
  s.dt = 5e-8;
  return s;
}

SolverSetup friction_with_obstacle() {
  SolverSetup s = paper_mixture(0.5);
  s.contacts = ContactSettings::uniform(2, 0.5, 0.4);
  s.obstacle = make_obstacle(ObstacleShape::cylinder, {0, 0, 0}, {10e-3}, aluminium());
  s.dt = 3e-8;
  return s;
}

SolverSetup in_3d(SolverSetup s) {
  s.dim = 3;
  return s;
}

}  // namespace

TEST(BackendAgreement, FrictionlessDouble) {
  compare_backends(frictionless(), 3000);
}

TEST(BackendAgreement, FrictionWithObstacleDouble) {
  compare_backends(friction_with_obstacle(), 3000);
}

TEST(BackendAgreement, FrictionlessSingle) {
  SolverSetup s = paper_mixture(0.9);
  s.precision = Precision::single_precision;
  s.dt = 5e-8;
  compare_backends(s, 3000);
}

TEST(FusedStep, MatchesSeparateHalvesFrictionless) {
  compare_fused_with_separate_halves(frictionless(), 2000);
}

TEST(FusedStep, MatchesSeparateHalvesWithFrictionAndObstacle) {
  compare_fused_with_separate_halves(friction_with_obstacle(), 2000);
}

// 3-D: spin vectors, 3-component springs and the 27-cell search, bitwise as in 2-D.
TEST(BackendAgreement, FrictionWithObstacleIn3d) {
  compare_backends(in_3d(friction_with_obstacle()), 2000);
}

TEST(FusedStep, MatchesSeparateHalvesWithFrictionAndObstacleIn3d) {
  compare_fused_with_separate_halves(in_3d(friction_with_obstacle()), 1000);
}

namespace {

// Fused steps in one parallel region (kernels/solver/fused_steps.hpp) against one region
// per step: the same list builds and bitwise the same particles, with fewer regions.
void compare_regions(SolverSetup s, int steps) {
  const HostParticles gas = make_gas(s);
  SolverSetup one_per_step = s;
  one_per_step.steps_per_region = 1;
  // Regions of many steps are host paths only (docs/cuda.md, "Branch points").
  auto many = test::make_solver_on_paths(s, gas.size(), test::Paths::host);
  auto single = test::make_solver_on_paths(one_per_step, gas.size(), test::Paths::host);
  many->set_particles(gas);
  single->set_particles(gas);
  many->advance(steps);
  single->advance(steps);
  EXPECT_EQ(single->step_regions(), steps - 1);  // the last step is not fused
  EXPECT_LT(many->step_regions(), (steps - 1) / 4);
  EXPECT_EQ(many->list_builds(), single->list_builds());
  EXPECT_EQ(many->exact_list_checks(), single->exact_list_checks());
  EXPECT_GT(many->list_builds(), 1);
  expect_bitwise_identical(many->particles(), single->particles());
}

}  // namespace

TEST(FusedSteps, ManyStepsPerRegionMatchOnePerStepFrictionless) {
  compare_regions(frictionless(), 2000);
}

TEST(FusedSteps, ManyStepsPerRegionMatchOnePerStepWithFrictionAndObstacle) {
  compare_regions(friction_with_obstacle(), 2000);
}

namespace {

// Host paths against device paths (kernels/device/backends.hpp; docs/cuda.md, "Branch
// points"): the one-visit list build against count, scan and fill, runs of 64 particles
// per work item against one, many fused steps per region against one, the field sums'
// strategies. None changes a particle's arithmetic or the order of its contacts, so the
// trajectories are bitwise the same. Each solver shows that it took its own branches:
// only host paths run many steps in one region.
void compare_paths(SolverSetup s, int steps) {
  const HostParticles gas = make_gas(s);
  auto host = test::make_solver_on_paths(s, gas.size(), test::Paths::host);
  auto device = test::make_solver_on_paths(s, gas.size(), test::Paths::device);
  host->set_particles(gas);
  device->set_particles(gas);
  host->advance(steps);
  device->advance(steps);
  EXPECT_LT(host->step_regions(), (steps - 1) / 4) << host->variant();
  EXPECT_EQ(device->step_regions(), steps - 1) << device->variant();
  EXPECT_EQ(host->list_builds(), device->list_builds());
  EXPECT_GT(host->list_builds(), 1);
  EXPECT_GT(host->diagnostics().contacts, 0);
  expect_bitwise_identical(host->particles(), device->particles());
  EXPECT_EQ(host->contact_pairs(), device->contact_pairs());
}

}  // namespace

TEST(KernelPaths, DeviceTrajectoryIsTheHostTrajectoryBitwiseFrictionless) {
  compare_paths(frictionless(), 3000);
}

TEST(KernelPaths, DeviceTrajectoryIsTheHostTrajectoryBitwiseWithFrictionAndObstacle) {
  compare_paths(friction_with_obstacle(), 3000);
}

namespace {

// Device paths chain their steps (kernels/solver/chained_steps.hpp): the rebuild watch on
// the device, read by the host once per chain. How many steps a chain queues changes what
// the host waits for, never the trajectory: one step per chain (steps_per_region = 1),
// chains of up to 7 and calls of one step against the default, and each against host
// paths.
void compare_chain_lengths(SolverSetup s, int steps) {
  const HostParticles gas = make_gas(s);
  SolverSetup one = s, seven = s;
  one.steps_per_region = 1;
  seven.steps_per_region = 7;
  auto host = test::make_solver_on_paths(s, gas.size(), test::Paths::host);
  std::vector<std::unique_ptr<Solver>> chained;
  for (const SolverSetup& setup : {s, one, seven})
    chained.push_back(test::make_solver_on_paths(setup, gas.size(), test::Paths::device));
  // And calls of one step each, which have nothing to chain (device paths, all alike).
  chained.push_back(test::make_solver_on_paths(s, gas.size(), test::Paths::device));
  host->set_particles(gas);
  host->advance(steps);
  for (auto& solver : chained) {
    solver->set_particles(gas);
    if (solver == chained.back()) {
      for (int k = 0; k < steps; ++k) solver->advance(1);
    } else {
      solver->advance(steps);
    }
    EXPECT_EQ(solver->list_builds(), host->list_builds());
    EXPECT_EQ(solver->exact_list_checks(), host->exact_list_checks());
    EXPECT_EQ(solver->steps_done(), host->steps_done());
    expect_bitwise_identical(solver->particles(), host->particles());
  }
  EXPECT_GT(host->list_builds(), 1);
}

}  // namespace

TEST(ChainedSteps, AnyChainLengthGivesTheHostTrajectoryFrictionless) {
  compare_chain_lengths(frictionless(), 2000);
}

TEST(ChainedSteps, AnyChainLengthGivesTheHostTrajectoryWithFrictionAndObstacle) {
  compare_chain_lengths(friction_with_obstacle(), 2000);
}

// Every step reporting its exact displacement, and the adaptive skin choosing a new skin
// at each build: the device's watch asks as the host's does.
TEST(ChainedSteps, ExactListCheckAndAdaptiveSkinGiveTheHostTrajectory) {
  SolverSetup exact = frictionless();
  exact.exact_list_check = true;
  compare_chain_lengths(exact, 1500);
  SolverSetup adaptive = frictionless();
  adaptive.adaptive_skin = true;
  compare_chain_lengths(adaptive, 1500);
}

namespace {

// The threads' shares in regions of many steps (kernels/solver/thread_shares.hpp): cut by
// measured time, equal, or moved at every region (a quarter and three quarters of the
// particles in turn). Who moves a particle never changes how, so the trajectories are
// bitwise the same.
void compare_thread_shares(SolverSetup s, int steps) {
  if (Kokkos::DefaultExecutionSpace().concurrency() < 2)
    GTEST_SKIP() << "needs 2 or more threads (OMP_NUM_THREADS=2)";
  const HostParticles gas = make_gas(s);
  using Mode = ThreadShareMode;
  std::vector<std::unique_ptr<Solver>> solvers;
  for (const Mode mode : {Mode::equal, Mode::alternating, Mode::by_time}) {
    SolverSetup setup = s;
    setup.thread_shares = mode;
    solvers.push_back(test::make_solver_on_paths(setup, gas.size(), test::Paths::host));
    solvers.back()->set_particles(gas);
    solvers.back()->advance(steps);
  }
  const ThreadShareStats equal = solvers[0]->thread_shares(),
                         alternating = solvers[1]->thread_shares();
  ASSERT_EQ(equal.shares.size(), 2u) << "no region of many steps ran";
  EXPECT_NEAR(equal.shares[0], 0.5, 0.02);
  EXPECT_EQ(equal.moves, 0);
  // Every region of many steps moved the alternating cuts, to a quarter or three quarters
  // (runs of 64 particles).
  EXPECT_LE(alternating.moves, solvers[1]->step_regions());
  EXPECT_GT(alternating.moves, 2);
  EXPECT_NEAR(std::min(alternating.shares[0], alternating.shares[1]), 0.25, 0.03);
  for (const auto& solver : solvers) {
    EXPECT_EQ(solver->list_builds(), solvers[0]->list_builds());
    expect_bitwise_identical(solver->particles(), solvers[0]->particles());
  }
  EXPECT_GT(solvers[0]->list_builds(), 1);
}

}  // namespace

TEST(ThreadShares, CutsNeverChangeTheTrajectoryFrictionless) {
  compare_thread_shares(frictionless(), 2000);
}

TEST(ThreadShares, CutsNeverChangeTheTrajectoryWithFrictionAndObstacle) {
  compare_thread_shares(friction_with_obstacle(), 2000);
}

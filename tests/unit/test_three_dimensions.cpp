// The 3-D solver beyond its physics (tests/physics: Haff's law, energy, oblique impacts):
// insertion in 3-D (kernels/particles/population.hpp: candidates drawn in the box
// x_range x y_range x z_range, no sphere placed on another, the z velocity a Gaussian of
// the inflow's sigma from a stream of its own; 2-D insertion is checked by the runs,
// bitwise by reference.bitwise_unchanged), a 3-D state through export and import, and what
// 3-D refuses for now.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "models/obstacle_shapes.hpp"
#include "same_particles.hpp"

using namespace granshock;

namespace {

// The paper mixture of spheres in the box [0, hi) with the given periodic axes.
SolverSetup spheres_in_box(double restitution, double dt, const std::array<double, 3>& hi,
                           const std::array<bool, 3>& periodic) {
  SolverSetup s = paper_mixture(restitution);
  s.dim = 3;
  s.dt = dt;
  s.box.lo = {0, 0, 0};
  s.box.hi = hi;
  s.box.periodic = periodic;
  return s;
}

TEST(ThreeDimensions, InsertionFillsTheLayerWithoutOverlap) {
  const SolverSetup s = spheres_in_box(0.9, 1e-7, {0.04, 0.04, 0.003}, {true, false, false});
  auto solver = make_solver(s, 1024);
  InsertionRequest rq;
  rq.x_range = {0, 0.04};
  rq.y_range = {0, 0.01};
  rq.z_range = {0.5e-3, 2.5e-3};  // the centres of 1 mm spheres in a 3 mm layer
  const double volume = 0.04 * 0.01 * 2e-3, sphere = M_PI / 6 * 1e-9;
  rq.count = int(0.2 * volume / sphere);  // volume fraction 0.2: 305 spheres
  rq.number_fraction = {0.5, 0.5};
  rq.mean_velocity = {0, 1.0};
  rq.sigma_m_per_s = 0.1;
  rq.seed = 7;
  ASSERT_EQ(solver->insert(rq), rq.count);
  EXPECT_EQ(solver->diagnostics().contacts, 0);  // no sphere on another

  const HostParticles p = solver->particles();
  ASSERT_EQ(int(p.size()), rq.count);
  double z_min = 1, z_max = -1, vz_mean = 0, vz2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double z = p.position[i][2], vz = p.velocity[i][2];
    EXPECT_GE(z, rq.z_range[0]);
    EXPECT_LE(z, rq.z_range[1]);
    EXPECT_LE(p.position[i][1], rq.y_range[1]);
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
    vz_mean += vz / double(p.size());
    vz2 += vz * vz / double(p.size());
  }
  // Uniform in z: of 305 draws, none within a tenth of the range of either end has
  // probability 0.9^305 = 1e-14.
  EXPECT_LT(z_min, rq.z_range[0] + 0.2e-3);
  EXPECT_GT(z_max, rq.z_range[1] - 0.2e-3);
  // A Gaussian of sigma along z: the mean within 4 standard errors (sigma / sqrt(N)), the
  // variance within 4 of its relative standard deviations sqrt(2 / (N - 1)) = 8.1 %.
  const double n = double(p.size()), sigma2 = rq.sigma_m_per_s * rq.sigma_m_per_s;
  EXPECT_NEAR(vz_mean, 0, 4 * rq.sigma_m_per_s / std::sqrt(n));
  EXPECT_NEAR((vz2 - vz_mean * vz_mean) / sigma2, 1, 4 * std::sqrt(2 / (n - 1)));
}

// A dense frictional gas of spheres around the cylinder: its state (3 spin and torque
// values per particle, 16 history slots of 3-component springs) passes every check of a
// fresh solver's import_state, and both continue bitwise alike.
TEST(ThreeDimensions, StateImportsIntoAFreshSolverAndContinuesBitwise) {
  SolverSetup s = paper_mixture(0.5);
  s.dim = 3;
  s.contacts = ContactSettings::uniform(2, 0.5, 0.4);
  s.contacts.softening = 1000;             // contacts 16 times longer: many at any moment
  const GasSpec spec{1000, 0.45, 2.0, 5};  // lattice gaps of 0.05 d
  size_periodic_box(s, spec);
  const double middle = 0.5 * s.box.length(0);
  s.obstacle = make_obstacle(ObstacleShape::cylinder, {middle, middle, 0}, {4e-3}, aluminium());
  s.dt = 2e-7;
  const HostParticles lattice = make_homogeneous_gas(s, spec);
  HostParticles gas;  // none inside the cylinder
  for (std::size_t i = 0; i < lattice.size(); ++i)
    if (std::hypot(lattice.position[i][0] - middle, lattice.position[i][1] - middle) > 2.55e-3)
      gas.add(lattice.position[i], lattice.velocity[i], lattice.species[i], lattice.id[i]);
  auto solver = make_solver(s, gas.size());
  solver->set_particles(gas);
  solver->advance(2000);  // 0.8 d at the mean speed
  const SolverState state = solver->export_state();
  EXPECT_EQ(state.dim, 3);
  EXPECT_EQ(state.angular_velocity.size(), 3 * state.size());
  EXPECT_EQ(state.torque.size(), 3 * state.size());
  EXPECT_EQ(state.history_slots, 16);
  std::size_t partners = 0, on_obstacle = 0;
  for (int partner : state.history_partner) partners += partner >= 0;
  for (std::size_t k = 0; k < state.history_obstacle_spring.size(); k += 3)
    on_obstacle += state.history_obstacle_spring[k] != 0 ||
                   state.history_obstacle_spring[k + 1] != 0 ||
                   state.history_obstacle_spring[k + 2] != 0;
  std::printf("[ measured ] %zu spheres, %zu held springs, %zu on the cylinder\n", state.size(),
              partners, on_obstacle);
  EXPECT_GT(2 * partners, state.size()) << "too few contacts to test much";
  EXPECT_GE(on_obstacle, 3u) << "too few obstacle contacts to test much";

  auto fresh = make_solver(s, gas.size());
  ASSERT_NO_THROW(fresh->import_state(state));
  solver->advance(300);
  fresh->advance(300);
  test::expect_bitwise_identical(solver->particles(), fresh->particles());
}

// Deletion through the open z faces: a sphere past the box along z is deleted and counted
// on its face, as along x and y.
TEST(ThreeDimensions, SpheresLeavingAlongZAreDeletedAndCountedPerFace) {
  SolverSetup s = spheres_in_box(0.5, 1e-6, {0.01, 0.01, 0.004}, {true, true, false});
  s.delete_outside = true;
  HostParticles p;
  p.add({0.002, 0.002, 0.0015}, {0, 0, -1.0}, 0, 0);  // leaves through z = 0
  p.add({0.005, 0.005, 0.0025}, {0, 0, 1.0}, 1, 1);   // through z = 4 mm
  p.add({0.002, 0.007, 0.002}, {1.0, 0, 0}, 0, 2);    // stays (periodic along x)
  p.add({0.007, 0.002, 0.002}, {0, -1.0, 0}, 1, 3);   // stays (periodic along y)
  auto solver = make_solver(s, 8);
  solver->set_particles(p);
  solver->advance(3000);  // 3 mm at 1 m/s
  const RemovalCounts removed = solver->remove_escaped();
  EXPECT_EQ(removed.low[2], 1);
  EXPECT_EQ(removed.high[2], 1);
  EXPECT_EQ(removed.total(), 2);
  const HostParticles left = solver->particles();
  ASSERT_EQ(left.size(), 2u);
  for (std::size_t i = 0; i < left.size(); ++i) EXPECT_GE(left.id[i], 2);
}

TEST(ThreeDimensions, SinglePrecisionAndA2dSamplingLayoutAreRefused) {
  SolverSetup s = paper_mixture(0.5);
  s.dim = 3;
  s.dt = 1e-7;
  size_periodic_box(s, GasSpec{27, 0.1, 1.0, 1});
  s.precision = Precision::single_precision;
  EXPECT_THROW(make_solver(s, 27), UserError);
  s.precision = Precision::double_precision;
  auto solver = make_solver(s, 27);
  EXPECT_THROW(solver->configure_sampling(FieldSampling{}), std::logic_error);
  FieldSampling columns;
  columns.grid.dim = 3;
  columns.grid.depth = s.box.length(2);
  EXPECT_NO_THROW(solver->configure_sampling(columns));
  s.dim = 4;
  EXPECT_THROW(make_solver(s, 27), UserError);
}

}  // namespace

// What a solver exports for a checkpoint passes the checkpoint's own
// consistency checks (core/checkpoint_checks.hpp), also in the corner where a
// row freed by a deleted particle is reused by an inserted one.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/checkpoint_checks.hpp"
#include "core/solver.hpp"
#include "models/obstacle_shapes.hpp"
#include "same_particles.hpp"

using namespace granshock;

namespace {

double distance_from_obstacle(const SolverSetup& s, const std::array<double, 3>& x) {
  return std::hypot(x[0] - s.obstacle->centre[0], x[1] - s.obstacle->centre[1]);
}

// A dense frictional gas of soft particles (Young's modulus 1e-4 of the paper's, so a
// contact lasts ~0.1 ms) in a periodic box around a cylinder of 16 mm, none starting
// inside it: half of them touch at any time.
SolverSetup dense_frictional_gas(Precision precision, HostParticles& kept) {
  SolverSetup s = paper_mixture(0.3);
  s.contacts = ContactSettings::uniform(2, 0.3, 0.4);
  s.precision = precision;
  for (Species& species : s.species) species.material.youngs_modulus_pa *= 1e-4;
  s.dt = 2e-6;
  GasSpec spec;
  spec.particles = 1500;
  spec.area_fraction = 0.4;
  spec.sigma_m_per_s = 2.0;
  size_periodic_box(s, spec);
  s.obstacle =
      make_obstacle(ObstacleShape::cylinder, {0.5 * s.box.length(0), 0.5 * s.box.length(1), 0},
                    {16e-3}, aluminium());
  HostParticles gas = make_homogeneous_gas(s, spec);
  for (std::size_t i = 0; i < gas.size(); ++i)
    if (distance_from_obstacle(s, gas.position[i]) > 8.6e-3)
      kept.add(gas.position[i], gas.velocity[i], gas.species[i], gas.id[i]);
  return s;
}

// A frictional channel 10 mm wide (periodic) and tall (open, deleting).
SolverSetup channel() {
  SolverSetup s = paper_mixture(0.5);
  s.contacts = ContactSettings::uniform(2, 0.5, 0.5);
  s.box.lo = {0, 0, 0};
  s.box.hi = {0.01, 0.01, 1};
  s.box.periodic = {true, false, false};
  s.delete_outside = true;
  s.dt = 1e-7;
  return s;
}

}  // namespace

// Particle A leaves through the top while sliding along B, so B's row held a
// contact history when the deletion compacted the rows; the particle inserted
// next reuses that row. Before the fix the new particle inherited B's old
// spring in a free slot.
TEST(StateExport, InsertedParticleReusingADeletedRowHasAnEmptyHistory) {
  for (const Precision precision : {Precision::double_precision, Precision::single_precision}) {
    SolverSetup setup = channel();
    setup.precision = precision;
    auto solver = make_solver(setup, 4);
    // A, 1 um below the top, leaves in 10 steps; B slides past it, 10 nm to its
    // side, and the two close that gap within 5 steps (a contact of ~70 steps).
    HostParticles start;
    start.add({0.005, 0.009999, 0}, {0.01, 1.0, 0}, 0, 0);
    start.add({0.00600001, 0.009999, 0}, {-0.01, 0, 0}, 0, 1);
    solver->set_particles(start);
    solver->advance(30);  // A is outside; no rebuild (it moved 3 um, skin/2 is 0.15 mm)
    SolverState before = solver->export_state();
    ASSERT_EQ(before.size(), 2u);
    bool spring = false;
    for (double xi : before.history_spring) spring = spring || xi != 0;
    ASSERT_TRUE(spring) << "A and B must still slide in contact";
    EXPECT_EQ(solver->remove_escaped().high[1],
              1);  // A deleted, B compacted to row 0

    InsertionRequest rq;
    rq.x_range = {0, 0.01};
    rq.y_range = {0.001, 0.003};
    rq.count = 1;
    rq.number_fraction = {1.0, 0.0};
    rq.mean_velocity = {0, 1.0};
    ASSERT_EQ(solver->insert(rq), 1);
    const SolverState after = solver->export_state();
    for (std::size_t k = 0; k < after.history_partner.size(); ++k) {
      if (after.history_partner[k] != -1) continue;
      for (std::size_t d = 0; d < 2; ++d) {
        EXPECT_EQ(after.history_spring[2 * k + d], 0.0)
            << "free slot " << k
            << (precision == Precision::single_precision ? " (single)" : " (double)");
      }
    }
    EXPECT_NO_THROW(check_state(after));
  }
}

// A dense frictional gas of soft particles (Young's modulus 1e-4 of the
// paper's, so a contact lasts ~0.1 ms) around an obstacle: half of them touch
// at any time, which the bow-shock runs of the other tests never reach. Its
// exported state passes every check of a fresh solver's import (neighbour list
// rebuilt and compared, contact history, forces of particles without contacts,
// obstacle springs) and comes back out unchanged.
TEST(StateExport, DenseFrictionalGasImportsIntoAFreshSolverUnchanged) {
  for (const Precision precision : {Precision::double_precision, Precision::single_precision}) {
    SCOPED_TRACE(precision == Precision::single_precision ? "single" : "double");
    HostParticles kept;
    const SolverSetup s = dense_frictional_gas(precision, kept);
    auto solver = make_solver(s, kept.size());
    solver->set_particles(kept);
    solver->advance(300);
    const SolverState state = solver->export_state();
    std::size_t partners = 0;
    for (int p : state.history_partner) partners += p >= 0;
    std::size_t on_obstacle = 0;
    for (std::size_t k = 0; k < state.history_obstacle_spring.size(); k += 2)
      on_obstacle +=
          state.history_obstacle_spring[k] != 0 || state.history_obstacle_spring[k + 1] != 0;
    EXPECT_GT(2 * partners, state.size()) << "too few contacts to test much";
    EXPECT_GE(on_obstacle, 3u) << "too few obstacle contacts to test much";
    auto fresh = make_solver(s, kept.size());
    EXPECT_NO_THROW(fresh->import_state(state));
    const SolverState back = fresh->export_state();
    EXPECT_EQ(back.position, state.position);
    EXPECT_EQ(back.history_partner, state.history_partner);
    EXPECT_EQ(back.neighbours, state.neighbours);
  }
}

// Particles given by position and velocity (Solver::set_particles) start with every other
// array at its rest value (particles/particle_store.hpp: StateArray::rest), also in a solver
// that held sliding contacts before: no spring, no partner, no obstacle spring is left over,
// and the given spins arrive.
TEST(StateExport, GivenParticlesStartAtRestInASolverThatHeldContacts) {
  SolverSetup setup = channel();
  setup.box.periodic = {true, true, false};
  setup.delete_outside = false;
  auto solver = make_solver(setup, 4);
  HostParticles sliding;
  sliding.add({0.005, 0.005, 0}, {0.01, 0.1, 0}, 0, 0);
  sliding.add({0.00600001, 0.005, 0}, {-0.01, -0.1, 0}, 0, 1);
  solver->set_particles(sliding);
  solver->advance(20);
  bool spring = false;
  for (double xi : solver->export_state().history_spring) spring = spring || xi != 0;
  ASSERT_TRUE(spring) << "the two must slide in contact first";

  HostParticles apart;  // 3 mm apart: no contact
  apart.add({0.002, 0.005, 0}, {0, 0.1, 0}, 0, 5);
  apart.add({0.006, 0.005, 0}, {0, -0.1, 0}, 1, 6);
  apart.angular_velocity = {3.0, -2.0};
  solver->set_particles(apart);
  const SolverState s = solver->export_state();
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.id, (std::vector<int>{5, 6}));
  EXPECT_EQ(s.angular_velocity, (std::vector<double>{3.0, -2.0}));
  for (int partner : s.history_partner) EXPECT_EQ(partner, -1);
  for (double xi : s.history_spring) EXPECT_EQ(xi, 0.0);
  for (double xi : s.history_obstacle_spring) EXPECT_EQ(xi, 0.0);
  for (double f : s.force) EXPECT_EQ(f, 0.0);
  for (double t : s.torque) EXPECT_EQ(t, 0.0);
  EXPECT_NO_THROW(check_state(s));
}

// A state imported into a solver that ran another one (the backend switch moves the run's
// state between two solvers, back and forth) continues as in the solver that exported it:
// nothing the other solver derived from its own particles survives the import. Before the
// fix the fused step kept the other state's marks of the particles near the obstacle
// (kernels/solver/run_marks.hpp), and those of this state that touched it went
// through.
TEST(StateExport, AStateImportedIntoASolverThatRanAnotherContinuesAsInItsOwn) {
  HostParticles kept;
  const SolverSetup s = dense_frictional_gas(Precision::double_precision, kept);
  auto own = make_solver(s, kept.size());
  own->set_particles(kept);
  own->advance(300);
  const SolverState state = own->export_state();
  // The other solver ran the particles far from the obstacle alone: none of its runs was
  // near it.
  HostParticles far;
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (distance_from_obstacle(s, kept.position[i]) > 20e-3)
      far.add(kept.position[i], kept.velocity[i], kept.species[i], kept.id[i]);
  auto other = make_solver(s, kept.size());
  other->set_particles(far);
  other->advance(10);
  other->import_state(state);
  own->advance(200);
  other->advance(200);
  test::expect_bitwise_identical(own->particles(), other->particles());
}

// What a solver exports for a checkpoint is consistent, also in the corner where a row
// freed by a deleted particle is reused by an inserted one.
#include <gtest/gtest.h>

#include "homogeneous_gas.hpp"
#include "solver.hpp"

using namespace granshock;

namespace {

// A frictional channel 10 mm wide (periodic) and tall (open, deleting).
SystemSetup channel() {
  SystemSetup s = paper_mixture(0.5);
  s.contacts = ContactModel::uniform(2, 0.5, 0.5);
  s.box.lo = {0, 0, 0};
  s.box.hi = {0.01, 0.01, 1};
  s.box.periodic = {true, false, false};
  s.delete_outside = true;
  s.dt = 1e-7;
  return s;
}

}  // namespace

// Particle A leaves through the top while sliding along B, so B's row held a contact
// history when the deletion compacted the rows; the particle inserted next reuses that
// row. Before the fix the new particle inherited B's old spring in a free slot.
TEST(StateExport, InsertedParticleReusingADeletedRowHasAnEmptyHistory) {
  for (const Precision precision : {Precision::dual, Precision::single}) {
    SystemSetup setup = channel();
    setup.precision = precision;
    auto solver = make_solver(setup, 4);
    // A, 1 um below the top, leaves in 10 steps; B slides past it, 10 nm to its side,
    // and the two close that gap within 5 steps (a contact of ~70 steps).
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
    EXPECT_EQ(solver->remove_escaped().high[1], 1);  // A deleted, B compacted to row 0

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
            << "free slot " << k << (precision == Precision::single ? " (single)" : " (double)");
      }
    }
  }
}

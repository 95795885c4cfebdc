// The checks of core/checkpoint_checks.hpp one by one: a consistent checkpoint passes,
// and each kind of inconsistency is refused with a message naming its dataset.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/checkpoint_checks.hpp"
#include "core/obstacle.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Three particles in a 40 x 60 mm channel (periodic in x): 0 and 1 touch, 2 is alone.
struct Sample {
  SolverState s;
  CheckpointExtras e;
  SolverFit fit;
  RunFit run;

  Sample() {
    s.step = 100;
    s.next_id = 3;
    s.history_slots = 2;
    s.position = {0.010, 0.020, 0.0109, 0.020, 0.030, 0.040};
    s.reference_position = {0.0101, 0.0201, 0.0108, 0.0199, 0.0299, 0.0399};
    s.velocity = {0.1, 1.0, -0.1, 1.0, 0.0, 0.9};
    s.force = {1e-3, 0, -1e-3, 0, 0, 0};
    s.angular_velocity = {2.0, -1.0, 5.0};
    s.torque = {1e-7, -1e-7, 0};
    s.species = {0, 1, 0};
    s.id = {0, 1, 2};
    s.history_partner = {1, -1, 0, -1, -1, -1};
    s.history_spring = {1e-7, 0, 0, 0, -1e-7, 0, 0, 0, 0, 0, 0, 0};
    s.history_obstacle_spring = {0, 0, 0, 0, 0, 0};
    s.neighbour_offsets = {0, 1, 2, 2};
    s.neighbours = {1, 0};
    s.list_builds = 5;
    s.removed_high = {0, 0, 0};

    e.rng_counter = 4;
    e.inserted = 3;
    e.insertion_carry = 0.5;
    e.wall_seconds_so_far = 12.5;
    // One grid bin, two blocks, 16 quantities (2 species): block 0 sampled twice.
    e.bin_sums.assign(34, 0.0);
    const double block0[16] = {2, 0, 2, 0, 0, 2, 1, 0.5, 1, 0.25, 0.5, 1, 1e-9, 0, 0, 1e-9};
    for (int q = 0; q < 16; ++q) e.bin_sums[static_cast<std::size_t>(q)] = block0[q];
    e.bin_sums[32] = 2;
    e.bin_shape = {32, 0, 2};

    fit.box.hi = {0.040, 0.060, 1};
    fit.box.periodic = {true, false, false};
    fit.delete_outside = true;
    fit.history_slots = 2;
    fit.radius = {5e-4, 5e-4};
    fit.max_friction = 0.5;
    fit.distance_tolerance = 1e-9;

    run.total_steps = 1000;
    run.insertion_events = 4;
    run.max_carry = 10;
    run.dt = 2e-7;
    run.mass = {4.1e-6, 1.4e-6};
    run.inertia = {0.4 * 4.1e-6 * 2.5e-7, 0.4 * 1.4e-6 * 2.5e-7};
    run.max_diameter = 1e-3;
    run.inflow_energy = 0.5 * 2.75e-6 * 1.02;
    run.grid_sums = 32;
    run.quantities = 16;
    run.n_species = 2;
    run.samples = {2, 0};
  }

  void check_all() const {
    check_state(s);
    check_extras(e);
    check_fit(s, fit);
    check_contacts(s, fit);
    check_run(s, e, run);
  }
};

struct Case {
  const char* name;
  std::function<void(Sample&)> change;
  const char* expected;  // in the message
};

void expect_refusals(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Sample sample;
    c.change(sample);
    try {
      sample.check_all();
      ADD_FAILURE() << "accepted";
    } catch (const InvalidCheckpoint& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  }
}

TEST(CheckpointChecks, AConsistentCheckpointPasses) {
  EXPECT_NO_THROW(Sample().check_all());
}

TEST(CheckpointChecks, StateOnItsOwn) {
  expect_refusals({
      {"dim", [](Sample& x) { x.s.dim = 7; }, "/state@dim = 7"},
      {"negative step", [](Sample& x) { x.s.step = -1; }, "/state@step"},
      {"negative next_id", [](Sample& x) { x.s.next_id = -5; }, "/state@next_id"},
      {"slots", [](Sample& x) { x.s.history_slots = -1; }, "/state@history_slots"},
      {"builds", [](Sample& x) { x.s.list_builds = -2; }, "/state@list_builds"},
      {"negative skin", [](Sample& x) { x.s.skin = -1e-4; }, "/state@skin"},
      {"skin not finite", [](Sample& x) { x.s.skin = std::nan(""); }, "/state@skin"},
      {"build after the step", [](Sample& x) { x.s.last_build_step = x.s.step + 1; },
       "/state@last_build_step"},
      {"removed", [](Sample& x) { x.s.removed_low[1] = -1; }, "/state@removed_low[1]"},
      {"position rows", [](Sample& x) { x.s.position.pop_back(); }, "/state/position has 5"},
      {"species rows", [](Sample& x) { x.s.species.push_back(0); }, "/state/species"},
      {"torque without friction",
       [](Sample& x) {
         x.s.history_slots = 0;
         x.s.history_partner.clear();
         x.s.history_spring.clear();
         x.s.history_obstacle_spring.clear();
         x.s.angular_velocity.clear();
       },
       "/state/torque"},
      {"spring rows", [](Sample& x) { x.s.history_spring.resize(6); }, "/state/history_spring"},
      {"NaN velocity", [](Sample& x) { x.s.velocity[3] = kNaN; }, "/state/velocity[3] = nan"},
      {"inf force", [](Sample& x) { x.s.force[0] = -kInf; }, "/state/force[0] = -inf"},
      {"inf reference", [](Sample& x) { x.s.reference_position[5] = kInf; },
       "/state/reference_position[5]"},
      {"offsets size", [](Sample& x) { x.s.neighbour_offsets.pop_back(); },
       "/state/neighbour_offsets has 3"},
      {"offsets start", [](Sample& x) { x.s.neighbour_offsets[0] = 1; },
       "/state/neighbour_offsets[0] = 1"},
      {"offsets decrease",
       [](Sample& x) {
         x.s.neighbour_offsets = {0, 2, 1, 2};
       },
       "/state/neighbour_offsets[2]"},
      {"offsets end", [](Sample& x) { x.s.neighbours.push_back(1); },
       "/state/neighbour_offsets[3] = 2"},
      {"neighbour range", [](Sample& x) { x.s.neighbours[1] = 0x7fffffff; },
       "/state/neighbours[1] = 2147483647"},
      {"negative neighbour", [](Sample& x) { x.s.neighbours[0] = -1; }, "/state/neighbours[0]"},
      {"self neighbour", [](Sample& x) { x.s.neighbours[0] = 0; }, "lists itself"},
      {"negative id", [](Sample& x) { x.s.id[2] = -4; }, "/state/id[2] = -4"},
      {"id past next_id", [](Sample& x) { x.s.id[2] = 3; }, "/state/id[2] = 3"},
      {"twin ids", [](Sample& x) { x.s.id[2] = 1; }, "holds id 1 twice"},
      {"partner range", [](Sample& x) { x.s.history_partner[0] = 9; },
       "/state/history_partner[0] = 9"},
      {"own partner", [](Sample& x) { x.s.history_partner[0] = 0; }, "own id"},
      {"twin partner", [](Sample& x) { x.s.history_partner[1] = 1; }, "repeats slot 0"},
      {"spring of a free slot", [](Sample& x) { x.s.history_spring[9] = 1e-9; },
       "/state/history_spring[9]"},
  });
}

TEST(CheckpointChecks, RunCountersOnTheirOwn) {
  expect_refusals({
      {"inserted", [](Sample& x) { x.e.inserted = -1; }, "/run@inserted = -1"},
      {"outlet", [](Sample& x) { x.e.deleted_outlet = -3; }, "/run@deleted_outlet"},
      {"carry", [](Sample& x) { x.e.insertion_carry = kNaN; }, "/run@insertion_carry"},
      {"wall time", [](Sample& x) { x.e.wall_seconds_so_far = -1; }, "/run@wall_seconds_so_far"},
      {"CPU time < 0", [](Sample& x) { x.e.cpu_seconds_so_far = -2; }, "/run@cpu_seconds_so_far"},
      {"CPU time NaN", [](Sample& x) { x.e.cpu_seconds_so_far = kNaN; }, "/run@cpu_seconds_so_far"},
      {"shape entries",
       [](Sample& x) {
         x.e.bin_shape = {32, 2};
       },
       "/run/bin_shape has 2"},
      {"shape negative",
       [](Sample& x) {
         x.e.bin_shape = {34, -2, 2};
       },
       "/run/bin_shape[1]"},
      {"shape sum",
       [](Sample& x) {
         x.e.bin_shape = {30, 0, 2};
       },
       "adds up to 32"},
      {"NaN sum", [](Sample& x) { x.e.bin_sums[4] = kNaN; }, "/run/bin_sums[4] = nan"},
      {"fractional samples", [](Sample& x) { x.e.bin_sums[33] = 0.5; }, "/run/bin_sums[33]"},
  });
}

TEST(CheckpointChecks, StateAgainstTheSolver) {
  expect_refusals({
      {"dim", [](Sample& x) { x.fit.dim = 3; }, "/state@dim = 2, but the scene is 3-D"},
      {"species", [](Sample& x) { x.s.species[1] = -1000000; },
       "/state/species[1] = -1000000 is not a species"},
      {"species count", [](Sample& x) { x.fit.radius.pop_back(); }, "/state/species[1] = 1"},
      {"friction", [](Sample& x) { x.fit.history_slots = 8; }, "/state@history_slots = 2"},
      {"periodic deletion", [](Sample& x) { x.s.removed_high[0] = 1; }, "the axis is periodic"},
      {"no z axis", [](Sample& x) { x.s.removed_low[2] = 1; }, "no such axis"},
      {"long spring", [](Sample& x) { x.s.history_spring[0] = 1e300; }, "/state/history_spring[0]"},
      {"wall spring off the obstacle", [](Sample& x) { x.s.history_obstacle_spring[4] = 1e-9; },
       "/state/history_obstacle_spring[4]"},
      {"force without contact", [](Sample& x) { x.s.force[5] = 1.0; }, "/state/force[4]"},
      {"torque without contact", [](Sample& x) { x.s.torque[2] = 1e-9; }, "/state/torque[2]"},
      {"partner out of contact",
       [](Sample& x) {
         x.s.history_partner[4] = 0;  // particle 2 claims particle 0 (not its neighbour)
       },
       "/state/history_partner[4] = 0"},
      {"contact without partner",
       [](Sample& x) {
         x.s.history_partner[0] = -1;
         x.s.history_spring[0] = 0;
       },
       "lacks particle 1"},
      // docs/stability.md, the extremes: particles overlapping by 0.3 d, and a centre inside the
      // obstacle, are states the solver cannot have made.
      {"overlap past the contact law's range", [](Sample& x) { x.s.position[2] = 0.0107; },
       "particles 0 and 1 overlap by 0.3 of a diameter, past the contact law's range (0.2)"},
      {"centre inside the obstacle",
       [](Sample& x) {
         Obstacle o;
         o.centre = {0.030, 0.0405, 0};
         o.size[0] = 0.004;
         x.fit.obstacle_distance = [o](const double* p) {
           return obstacle_distance(o, p[0], p[1]);
         };
       },
       "particle 2 lies inside the obstacle"},
  });
}

TEST(CheckpointChecks, StateAgainstTheRun) {
  expect_refusals({
      {"step past the end", [](Sample& x) { x.s.step = 1001; }, "/state@step = 1001"},
      {"lost particle", [](Sample& x) { x.e.inserted = 4; }, "leaves 4 particles"},
      {"outlet count",
       [](Sample& x) {
         x.e.inserted = 4;
         x.s.removed_high[1] = 1;  // /run@deleted_outlet stays 0
       },
       "/run@deleted_outlet"},
      {"next id", [](Sample& x) { x.s.next_id = 0x7fffffff; }, "/state@next_id = 2147483647"},
      {"rng", [](Sample& x) { x.e.rng_counter = 3; }, "/run@rng_counter = 3"},
      {"carry", [](Sample& x) { x.e.insertion_carry = 1e300; }, "/run@insertion_carry"},
      {"builds", [](Sample& x) { x.s.list_builds = 1000000; }, "/state@list_builds"},
      {"speed", [](Sample& x) { x.s.velocity[1] = 1e300; }, "/state/velocity: the mean energy"},
      {"spin", [](Sample& x) { x.s.angular_velocity[2] = -1e300; }, "/state/angular_velocity"},
      {"force", [](Sample& x) { x.s.force[0] = 1e300; }, "/state/force[0]"},
      {"torque", [](Sample& x) { x.s.torque[1] = 1e300; }, "/state/torque[1]"},
      {"bin shape", [](Sample& x) { x.run.profile_sums = 32; }, "the scene's field sums have"},
      {"samples",
       [](Sample& x) {
         x.run.samples = {3, 0};
       },
       "/run/bin_sums[32] = 2 samples"},
      {"unsampled block", [](Sample& x) { x.e.bin_sums[20] = 1; },
       "/run/bin_sums[20] = 1 in block 1"},
      {"fractional count", [](Sample& x) { x.e.bin_sums[0] = 1.5; }, "/run/bin_sums[0] = 1.5"},
      {"huge count", [](Sample& x) { x.e.bin_sums[0] = 1e300; }, "/run/bin_sums[0]"},
      {"moments of an empty bin", [](Sample& x) { x.e.bin_sums[6] = 0; }, "/run/bin_sums[7]"},
      {"huge square", [](Sample& x) { x.e.bin_sums[5] = 1e300; }, "/run/bin_sums[3]"},
      {"negative square", [](Sample& x) { x.e.bin_sums[3] = -1; }, "/run/bin_sums[3]"},
      {"Cauchy-Schwarz", [](Sample& x) { x.e.bin_sums[2] = 3; }, "Cauchy-Schwarz"},
      {"virial", [](Sample& x) { x.e.bin_sums[13] = -1e300; }, "/run/bin_sums[13]"},
  });
}

}  // namespace
}  // namespace granshock

// Particles as bytes (core/particle_bytes.hpp): the parts of several ranks, concatenated
// in rank order, read back as one state in that order; a selection keeps every
// per-particle array of the chosen rows, whatever its width.
#include <gtest/gtest.h>

#include "core/particle_bytes.hpp"

using namespace granshock;

namespace {

// n frictional 2-D particles with 2 history slots, every value telling its particle.
SolverState numbered_state(int first_id, int n) {
  SolverState s;
  s.dim = 2;
  s.step = 7;
  s.history_slots = 2;
  for (int i = 0; i < n; ++i) {
    const double v = first_id + i;
    for (int d = 0; d < 2; ++d) {
      s.position.push_back(v + 0.1 * d);
      s.velocity.push_back(-v - 0.1 * d);
      s.force.push_back(2 * v + d);
      s.reference_position.push_back(v + 0.01 * d);
      s.history_obstacle_spring.push_back(3 * v + d);
    }
    s.angular_velocity.push_back(v / 2);
    s.torque.push_back(v / 4);
    s.species.push_back((first_id + i) % 2);
    s.id.push_back(first_id + i);
    for (int slot = 0; slot < 2; ++slot) {
      s.history_partner.push_back(first_id + i + 100 + slot);
      for (int d = 0; d < 2; ++d) s.history_spring.push_back(v + 10 * slot + d);
    }
  }
  return s;
}

}  // namespace

TEST(ParticleBytes, PartsInRankOrderReadBackAsOneState) {
  const SolverState a = numbered_state(0, 3), b = numbered_state(3, 0), c = numbered_state(3, 2);
  std::vector<char> parts = pack_particles(a);
  for (const SolverState* s : {&b, &c}) {
    const std::vector<char> more = pack_particles(*s);
    parts.insert(parts.end(), more.begin(), more.end());
  }
  SolverState all;
  append_particles(parts, all);
  const SolverState expected = numbered_state(0, 5);
  EXPECT_EQ(all.id, expected.id);
  EXPECT_EQ(all.position, expected.position);
  EXPECT_EQ(all.history_spring, expected.history_spring);
  EXPECT_EQ(all.history_partner, expected.history_partner);
  EXPECT_EQ(all.torque, expected.torque);
  EXPECT_EQ(all.reference_position, expected.reference_position);
}

TEST(ParticleBytes, SelectionKeepsEveryArrayOfTheChosenRows) {
  SolverState s = numbered_state(0, 5);
  s.neighbour_offsets = {0, 1, 1, 1, 1, 1};
  s.neighbours = {2};
  const SolverState picked = select_particles(s, {4, 1});
  EXPECT_EQ(picked.step, 7);
  EXPECT_EQ(picked.id, (std::vector<int>{4, 1}));
  EXPECT_EQ(picked.position, (std::vector<double>{4, 4.1, 1, 1.1}));
  EXPECT_EQ(picked.history_partner, (std::vector<int>{104, 105, 101, 102}));
  EXPECT_EQ(picked.history_spring, (std::vector<double>{4, 5, 14, 15, 1, 2, 11, 12}));
  EXPECT_EQ(picked.angular_velocity, (std::vector<double>{2, 0.5}));
  EXPECT_TRUE(picked.neighbours.empty()) << "a list indexes the whole state";
}

TEST(ParticleBytes, HostParticlesTravelAlike) {
  HostParticles a, b;
  a.add({1, 2, 0}, {3, 4, 0}, 0, 10);
  b.add({5, 6, 0}, {7, 8, 0}, 1, 11);
  b.add({9, 10, 0}, {11, 12, 0}, 0, 12);
  std::vector<char> parts = pack_particles(a);
  const std::vector<char> more = pack_particles(b);
  parts.insert(parts.end(), more.begin(), more.end());
  HostParticles all;
  append_particles(parts, all);
  EXPECT_EQ(all.id, (std::vector<int>{10, 11, 12}));
  EXPECT_EQ(all.position[2], (std::array<double, 3>{9, 10, 0}));
  EXPECT_EQ(all.species, (std::vector<int>{0, 1, 0}));
}

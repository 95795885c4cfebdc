// Bitwise comparison of two solvers' particles, the check behind every "same trajectory"
// test (backend agreement, fused steps, the skin test's bound, the adaptive skin).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>

#include "core/host_particles.hpp"

namespace granshock::test {

// The same particles in the same order, with bitwise the same state.
inline void expect_bitwise_identical(const HostParticles& a, const HostParticles& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.species, b.species);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    differing += a.position[i] != b.position[i] || a.velocity[i] != b.velocity[i];
  EXPECT_EQ(differing, 0u) << "particles whose state differs bitwise";
  EXPECT_EQ(a.angular_velocity, b.angular_velocity);
}

}  // namespace granshock::test

// The complete state of a solver on the host, as a checkpoint stores it: everything
// needed to continue a run bitwise, in the particle order the solver holds (cell order).
// Floating-point values are stored as double; a single-precision solver's values
// round-trip exactly (float -> double -> float).
#pragma once

#include <cstdint>
#include <vector>

namespace granshock {

struct SolverState {
  int dim = 2;
  long step = 0;      // steps done
  int next_id = 0;    // the next global id to hand out
  // Per particle, n = id.size(); vectors are flattened [particle][component].
  std::vector<double> position;          // n * dim
  std::vector<double> velocity;          // n * dim
  std::vector<double> force;             // n * dim (needed: the next half-step uses it)
  std::vector<double> angular_velocity;  // n, or empty without friction
  std::vector<double> torque;            // n, or empty without friction
  std::vector<int> species;              // n
  std::vector<int> id;                   // n
  // Contact history (friction only): slots per particle, partner ids (-1 free), springs.
  int history_slots = 0;
  std::vector<int> history_partner;        // n * slots
  std::vector<double> history_spring;      // n * slots * dim
  std::vector<double> history_wall_spring; // n * dim

  std::size_t size() const { return id.size(); }
};

}  // namespace granshock

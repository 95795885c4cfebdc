// The complete state of a solver on the host, as a checkpoint stores it: everything
// needed to continue a run bitwise, in the particle order the solver holds (cell order),
// including the neighbour list and the positions it was built at. Restoring it needs no
// list rebuild, so a checkpoint can be taken at any step without changing the run.
// Floating-point values are stored as double; a single-precision solver's values
// round-trip exactly (float -> double -> float).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace granshock {

// Spin values per particle: about z in 2-D, a vector in 3-D (kernels/device/spin.hpp).
constexpr int spin_components(int dim) {
  return dim == 2 ? 1 : 3;
}

struct SolverState {
  int dim = 2;
  long step = 0;    // steps done
  int next_id = 0;  // the next global id to hand out
  // Per particle, n = id.size(); vectors are flattened [particle][component].
  std::vector<double> position;  // n * dim
  std::vector<double> velocity;  // n * dim
  std::vector<double> force;     // n * dim (needed: the next half-step uses it)
  // n * spin_components(dim) (about z in 2-D, a vector in 3-D), or empty without friction
  std::vector<double> angular_velocity;
  std::vector<double> torque;  // as angular_velocity
  std::vector<int> species;    // n
  std::vector<int> id;         // n
  // Contact history (friction only): slots per particle, partner ids (-1 free), springs.
  int history_slots = 0;
  std::vector<int> history_partner;             // n * slots
  std::vector<double> history_spring;           // n * slots * dim
  std::vector<double> history_obstacle_spring;  // n * dim
  // The contact virial of the step's last force pass, for the field sample a resumed run
  // may take at its first step (docs/fields.md, "The contact virial"): n * dim * dim, or
  // empty where the solver held none (and in format-3 checkpoints written before it was
  // kept: io/checkpoint_file.hpp).
  std::vector<double> contact_virial;

  // The Verlet list and the reference positions of the skin criterion.
  std::vector<double> reference_position;  // n * dim
  std::vector<int> neighbour_offsets;      // n + 1
  std::vector<int> neighbours;             // neighbour_offsets[n]
  long list_builds = 0;
  // The skin the list was built with (0: the scene's, as format-3 checkpoints written
  // before the adaptive skin read) and the step of that build (adaptive skin: the next choice
  // measures the displacement per step since then).
  double skin = 0;
  long last_build_step = 0;
  // Particles deleted so far through the lower/upper face of each axis.
  std::array<long, 3> removed_low{0, 0, 0};
  std::array<long, 3> removed_high{0, 0, 0};

  std::size_t size() const { return id.size(); }
};

}  // namespace granshock

// Particles on the host in plain double precision: how they enter a solver and how a
// snapshot leaves it. Always 3 components; a 2-D solver ignores z.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace granshock {

struct HostParticles {
  std::vector<std::array<double, 3>> position;
  std::vector<std::array<double, 3>> velocity;
  // spin_components(dim) per particle (core/solver_state.hpp): about z in 2-D, a vector
  // in 3-D; empty = all zero
  std::vector<double> angular_velocity;
  std::vector<int> species;
  std::vector<int> id;

  std::size_t size() const { return position.size(); }
  void add(std::array<double, 3> x, std::array<double, 3> v, int s, int global_id) {
    position.push_back(x);
    velocity.push_back(v);
    species.push_back(s);
    id.push_back(global_id);
  }
};

}  // namespace granshock

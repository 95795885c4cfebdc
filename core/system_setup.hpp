// Everything a solver needs to know about a scene's physics, independent of how the
// scene was written down: species, contact parameters, box, obstacle, time step.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "domain.hpp"
#include "material.hpp"
#include "obstacle.hpp"
#include "pair_properties.hpp"

namespace granshock {

struct ContactModel {
  // Indexed [species_i][species_j] (symmetric) and [species] for the obstacle.
  std::vector<std::vector<double>> restitution;
  std::vector<std::vector<double>> friction;
  std::vector<double> wall_restitution;
  std::vector<double> wall_friction;
  // Clamp Fn >= 0 (no attraction at the end of a contact). Off by default, as in
  // LIGGGHTS, because only then does the model restore exactly e.
  bool limit_force = false;

  static ContactModel uniform(int n_species, double e, double mu);
  bool has_friction() const;
};

enum class Precision { single, dual };

struct SystemSetup {
  int dim = 2;
  Box box;
  std::vector<Species> species;
  ContactModel contacts;
  std::optional<CylinderObstacle> obstacle;
  double dt = 0;
  double skin_m = 0;  // Verlet skin; 0 picks 0.3 of the largest diameter
  std::array<double, 3> gravity{0, 0, 0};
  Precision precision = Precision::dual;
  // Particles beyond the box on an open axis are deleted (inflow/outflow scenes).
  bool delete_outside = false;

  double max_diameter() const;
  double skin() const { return skin_m > 0 ? skin_m : 0.3 * max_diameter(); }
  // Every pair the scene can form, particle-particle and particle-obstacle.
  std::vector<PairProperties> all_pairs() const;
  PairProperties pair(int a, int b) const;
  PairProperties wall_pair(int a) const;
};

}  // namespace granshock

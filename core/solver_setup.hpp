// Everything a solver needs to know about a scene's physics, independent of how the scene
// was written down: dimension, box, species, contact law and parameters, obstacle, time
// step, precision. The variant table picks the compiled solver from it
// (kernels/solver/variant_table.hpp).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "core/contact_settings.hpp"
#include "core/domain.hpp"
#include "core/material.hpp"
#include "core/obstacle.hpp"
#include "core/pair_properties.hpp"
#include "core/run_modes.hpp"

namespace granshock {

// Floating-point precision of positions, velocities and forces in the kernels.
enum class Precision { single_precision, double_precision };

struct SolverSetup {
  int dim = 2;
  Box box;
  std::vector<Species> species;
  ContactSettings contacts;
  std::optional<Obstacle> obstacle;
  double dt = 0;
  double skin_m = 0;  // Verlet skin; 0 picks 0.3 of the largest diameter
  // Re-choose the skin at each list build that a displacement forced, between
  // smallest_adaptive_skin() and skin() (core/skin_model.hpp); the cells stay sized for
  // skin().
  bool adaptive_skin = false;
  // Measure every particle's displacement every step instead of bounding it by the top
  // speed (kernels/neighbours/rebuild_watch.hpp): the same rebuild steps, slower; for
  // tests and benchmarks.
  bool exact_list_check = false;
  // One process: host backends run up to this many fused steps in one parallel region
  // (kernels/solver/fused_steps.hpp), device paths queue up to this many steps between two
  // reads by the host (kernels/solver/chained_steps.hpp); 1 gives one region, or one read,
  // per step. The trajectory is the same either way.
  long steps_per_region = 4096;
  // Host backends, those regions: how the threads' shares of the particles are cut
  // (core/run_modes.hpp, kernels/solver/thread_shares.hpp; alternating moves them to a
  // quarter and three quarters of the particles in turn). The trajectory is the same in
  // every mode.
  ThreadShareMode thread_shares = ThreadShareMode::by_time;
  // Host backends: build the Verlet list in one visit of the candidates
  // (kernels/neighbours/verlet_list.hpp); false visits them twice, as a device does. The
  // lists are the same either way.
  bool list_visits_once = true;
  std::array<double, 3> gravity{0, 0, 0};
  Precision precision = Precision::double_precision;
  // 3-D: the box's z faces are flat frictionless walls, which hold a slab of particles
  // (kernels/models/z_walls.hpp), of wall_material (a scene's: its obstacle's) with the
  // obstacle's restitution and calibrated damping (wall_pair).
  bool z_walls = false;
  Material wall_material = aluminium();
  // Particles beyond the box on an open axis are deleted (inflow/outflow scenes).
  bool delete_outside = false;

  double max_diameter() const;
  double skin() const { return skin_m > 0 ? skin_m : 0.3 * max_diameter(); }
  double smallest_adaptive_skin() const { return std::fmin(0.05 * max_diameter(), skin()); }
  // Every pair the scene can form, particle-particle and particle-obstacle.
  std::vector<PairProperties> all_pairs() const;
  PairProperties pair(int a, int b) const;
  PairProperties obstacle_pair(int a) const;
  PairProperties wall_pair(int a) const;  // z_walls only
};

}  // namespace granshock

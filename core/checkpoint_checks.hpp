// Everything a checkpoint's contents must satisfy before a run continues from it, in one
// place. A checkpoint whose checksum holds can still be wrong (written by a buggy
// build, edited and re-sealed): these checks keep such a state from crashing the
// solver or silently changing the run. Each failure throws InvalidCheckpoint, one line
// naming the dataset (as in docs/output_format.md) and what is wrong with it.
//
// Three levels, by what they need to know:
//   check_state, check_extras  the file alone (io, right after reading);
//   check_fit, check_contacts  the solver the scene builds (StateTransfer::import_state);
//   check_run                  the run loop's schedule and physics (BowShockRun::resume).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/checkpoint_extras.hpp"
#include "core/domain.hpp"
#include "core/solver_state.hpp"
#include "core/user_error.hpp"

namespace granshock {

class InvalidCheckpoint : public UserError {
 public:
  using UserError::UserError;
};

// The one-line refusal that names the file: "checkpoint 'F' is invalid: <detail>; ...".
UserError refuse_checkpoint(const std::filesystem::path& file, const InvalidCheckpoint& e);

// Shapes that agree with each other, indices and ids in range, finite values, counts
// that cannot be negative, bin_shape consistent with bin_sums.
void check_state(const SolverState& s);
void check_extras(const CheckpointExtras& e);

// What a solver built for the scene expects of a state.
struct SolverFit {
  int dim = 2;
  int history_slots = 0;  // 0 without friction
  Box box;
  bool delete_outside = false;
  std::vector<double> radius;  // per species
  double max_friction = 0;     // largest Coulomb coefficient of any pair
  // The signed distance of a point (its dim coordinates) from the obstacle's surface,
  // negative inside; empty without an obstacle. Given by the solver, which knows the shapes
  // (models/obstacle_shapes.hpp): core does not.
  std::function<double(const double* position)> obstacle_distance;
  // Distances within this of a contact distance are not judged: the solver rounds
  // positions to its precision (a few ulps of the box's extent).
  double distance_tolerance = 0;
};

// Dimension, species indices, the friction arrays of this solver, deletion counts only
// through faces that delete, tangential springs of a plausible length.
void check_fit(const SolverState& s, const SolverFit& fit);
// Contact state that follows from the positions (call after the neighbour list is known
// to be the one the positions give): a particle without contacts carries no force, no
// torque and no obstacle spring, and it keeps a history slot for exactly the neighbours
// it touches.
void check_contacts(const SolverState& s, const SolverFit& fit);

// What the run loop knows at the checkpoint's step.
struct RunFit {
  long total_steps = 0;
  std::uint64_t insertion_events = 0;  // batches drawn by this step, prefill included
  double max_carry = 0;                // the particles the batches since prefill asked for
  double dt = 0;
  std::vector<double> mass, inertia;  // per species
  double max_diameter = 0;
  double inflow_energy = 0;  // kinetic energy of a particle at the inflow, J
  // Field sums: grid and profile lengths, samples per block due by this step.
  long grid_sums = 0, profile_sums = 0;
  int quantities = 0, n_species = 0;  // per bin (core/bin_layout.hpp)
  int dim = 2;                        // 3: the z moments and W_zz follow the virial
  std::vector<long> samples;
};

// Counters that agree with each other and with the schedule, a state that passes the
// run's health check, forces and torques that do not blow it up within a step, and
// field sums of the scene's shape whose moments are consistent (core/bin_layout.hpp).
void check_run(const SolverState& s, const CheckpointExtras& e, const RunFit& fit);

}  // namespace granshock

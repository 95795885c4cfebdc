// The measuring part of the solver interface (core/solver.hpp): energies, contacts and
// species moments of the current state, the time loop's counters, and on several
// processes what the halo exchange has cost.
#pragma once

#include <array>
#include <utility>
#include <vector>

namespace granshock {

struct Diagnostics {
  double kinetic_energy = 0;     // translational, 1/2 m v^2 summed
  double rotational_energy = 0;  // 1/2 I omega^2 summed
  double elastic_energy = 0;     // Hertz normal springs: 8/15 Y* sqrt(R*) dn^(5/2)
  long contacts = 0;             // particle pairs plus particle-obstacle contacts
  std::array<double, 3> momentum{0, 0, 0};
  long non_finite = 0;  // particles with a NaN or infinite position or velocity
  // Particles whose centre lies inside the obstacle: a contact keeps a centre at least
  // R + r - (the largest overlap, 0.2 d: docs/contact_model.md) from the axis, so one
  // there was pushed through the surface (docs/stability.md).
  long inside_obstacle = 0;

  double total_energy() const { return kinetic_energy + rotational_energy + elastic_energy; }
};

// Per-species sums over the owned particles (for temperatures and mean velocities).
struct SpeciesMoments {
  long count = 0;
  std::array<double, 3> velocity_sum{0, 0, 0};
  double speed_squared_sum = 0;  // sum of |v|^2 over the in-plane components
};

// Several processes (docs/parallel.md): what exchanging particles with the neighbouring
// slabs has cost this process so far.
struct HaloStats {
  // Wall time (packing and waits included) in the halo updates between rebuilds, and in
  // the migration and ghost set-up at rebuilds (which scan the owned particles and the
  // global cell grid).
  double seconds = 0;
  double rebuild_seconds = 0;
  // Wall time in the per-step global maximum that decides a list rebuild: where a rank
  // waits for the slowest one (load imbalance) and pays the reduction's latency.
  double sync_seconds = 0;
  double bytes_sent = 0;  // to the neighbours
  long ghosts = 0;        // ghosts held since the last list rebuild
  long rebalances = 0;    // times the slab boundaries moved (--balance particles, work)
  long migrated = 0;      // particles handed to another slab at rebuilds (once per hop)
  double exchange_seconds() const { return seconds + rebuild_seconds; }
};

// Host regions of many steps (kernels/solver/thread_shares.hpp): each thread's share of
// the particles in the last region (empty: no such region ran), how often the balance by
// time moved the cuts, and the last region's slowest share over the mean (1: balanced).
struct ThreadShareStats {
  std::vector<double> shares;
  long moves = 0;
  double imbalance = 1;
};

class SolverStatistics {
 public:
  virtual ~SolverStatistics() = default;

  virtual Diagnostics diagnostics() const = 0;
  // Touching particle pairs as (smaller global id, larger global id), sorted.
  virtual std::vector<std::pair<int, int>> contact_pairs() const = 0;
  virtual std::vector<SpeciesMoments> species_moments() const = 0;
  // Several processes: the exchange's cost so far. One process: no cost.
  virtual HaloStats halo_stats() const = 0;

  virtual long steps_done() const = 0;
  virtual long list_builds() const = 0;
  // Exact displacement passes made because the speed bound of the skin test failed
  // (kernels/neighbours/rebuild_watch.hpp); a measure of what the bound saves.
  virtual long exact_list_checks() const = 0;
  // Parallel regions that ran fused steps: one per step, or one per run of steps with
  // SolverSetup::steps_per_region > 1 (kernels/solver/fused_steps.hpp).
  virtual long step_regions() const = 0;
  virtual ThreadShareStats thread_shares() const = 0;
};

}  // namespace granshock

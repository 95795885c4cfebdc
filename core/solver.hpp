// The interface every compiled solver variant offers to apps and tests. A variant is
// one instantiation of the kernels for what a scene needs (dimension, precision,
// friction, obstacle); make_solver picks it once, at start-up.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/bin_layout.hpp"
#include "core/communicator.hpp"
#include "core/host_particles.hpp"
#include "core/snapshot_part.hpp"
#include "core/solver_setup.hpp"
#include "core/solver_state.hpp"

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

// New particles for a rectangular region (2-D: x and y ranges), placed at random
// without overlapping each other or particles already there.
struct InsertionRequest {
  std::array<double, 2> x_range{0, 0};
  std::array<double, 2> y_range{0, 0};
  int count = 0;                        // particles wanted
  std::vector<double> number_fraction;  // per species, sums to 1
  std::array<double, 2> mean_velocity{0, 0};
  double sigma_m_per_s = 0;  // Gaussian fluctuation per component
  std::uint64_t seed = 0;
  std::uint64_t event = 0;    // insertion event number: the RNG stream
  long inserted_before = 0;   // particles inserted by earlier events
  bool rebuild_lists = true;  // false: the caller inserts more before the next step
};

// Particles deleted because they left through an open boundary, counted per face.
struct RemovalCounts {
  std::array<long, 3> low{0, 0, 0};   // through the lower face of each axis
  std::array<long, 3> high{0, 0, 0};  // through the upper face
  long total() const { return low[0] + low[1] + low[2] + high[0] + high[1] + high[2]; }
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

// Where slab boundaries lie on several processes (docs/parallel.md, "Load balance"):
// equal slabs of cell rows, or moved at list rebuilds to balance the particle count or the
// measured compute time. The choice never changes the results, only who computes what.
enum class SlabBalance { equal, particles, work };

// How several processes divide the box (docs/parallel.md): slabs of cell rows along x
// (across the flow, through the periodic faces) or along y (along the flow), and how
// their boundaries move. Neither choice changes the results.
enum class SlabAxis { x = 0, y = 1 };
struct Decomposition {
  SlabAxis axis = SlabAxis::y;
  SlabBalance balance = SlabBalance::equal;
};

class Solver {
 public:
  virtual ~Solver() = default;

  virtual void set_particles(const HostParticles& particles) = 0;
  // Deletes escaped particles, sorts by cell and rebuilds the neighbour list now (the time
  // loop does it by itself whenever a particle has moved half the skin).
  virtual void rebuild_lists() = 0;
  virtual HostParticles particles() const = 0;  // copies the owned particles to the host
  virtual void advance(long steps) = 0;
  virtual Diagnostics diagnostics() const = 0;
  // Touching particle pairs as (smaller global id, larger global id), sorted.
  virtual std::vector<std::pair<int, int>> contact_pairs() const = 0;
  virtual std::vector<SpeciesMoments> species_moments() const = 0;

  // Inserts up to request.count particles (fewer when there is no room); new ids are
  // consecutive from next_id(). Returns how many were inserted.
  virtual int insert(const InsertionRequest& request) = 0;
  // Deletes particles outside the box on open axes when setup.delete_outside is set
  // (also done at every neighbour-list rebuild); returns all deletions so far.
  virtual RemovalCounts remove_escaped() = 0;
  virtual RemovalCounts removed() const = 0;
  virtual int next_id() const = 0;

  // Field sampling (docs/fields.md): configure once, then add samples to a block.
  virtual void configure_sampling(const FieldSampling& sampling) = 0;
  virtual void sample_fields(int block) = 0;
  // The sums as host arrays ([blocks][ny][nx][q] and [blocks][n][q]), and their restore.
  virtual std::vector<double> field_sums(bool profile) const = 0;
  virtual void restore_field_sums(const std::vector<double>& grid,
                                  const std::vector<double>& profile) = 0;

  // Several processes (docs/parallel.md): export_state is collective and returns the whole
  // state, as one process would hold it, on rank 0 (the scalars alone elsewhere);
  // import_state takes the whole state on every rank, whatever the number of ranks that
  // wrote it.
  virtual SolverState export_state() const = 0;
  // Continues from a checkpoint's state; a state that does not fit this solver (another
  // dimension, unknown species, a neighbour list its positions do not give, ...) is
  // refused with InvalidCheckpoint (core/checkpoint_checks.hpp) before anything changes.
  virtual void import_state(const SolverState& state) = 0;

  // Several processes: the slabs' axis and how their boundaries move at list rebuilds,
  // chosen before any particle is placed; the exchange's cost so far. One process:
  // nothing to divide, no cost.
  virtual void decompose(const Decomposition& decomposition) = 0;
  virtual HaloStats halo_stats() const = 0;

  virtual std::size_t size() const = 0;  // the particles this process owns
  virtual long global_size() const = 0;  // on every process (collective)
  // This process's part of a snapshot, with the rows it fills in one process's order
  // (collective; one process: all of them, rows [0, n)).
  virtual SnapshotPart snapshot_part() const = 0;
  virtual long steps_done() const = 0;
  virtual long list_builds() const = 0;
  // Exact displacement passes made because the speed bound of the skin test failed
  // (kernels/neighbours/rebuild_watch.hpp); a measure of what the bound saves.
  virtual long exact_list_checks() const = 0;
  // Parallel regions that ran fused steps: one per step, or one per run of steps with
  // SolverSetup::steps_per_region > 1 (kernels/solver/fused_steps.hpp).
  virtual long step_regions() const = 0;
  // The Verlet skin the current list was built with (m): the scene's, or with
  // SolverSetup::adaptive_skin the last choice of core/skin_model.hpp.
  virtual double skin() const = 0;
  virtual double time() const = 0;
  virtual std::string variant() const = 0;  // e.g. "2d/double/frictionless/obstacle/OpenMP"
};

enum class Backend { default_space, serial };

// The one place where a scene's needs select a compiled kernel variant
// (kernels/solver/variant_table.hpp). `comm` carries the global reductions
// (communicator.hpp); by default one process owns everything.
std::unique_ptr<Solver> make_solver(const SolverSetup& setup, std::size_t capacity,
                                    Backend backend = Backend::default_space,
                                    const Communicator* comm = nullptr);

// The default backend's threads when it runs on the host's threads beside a separate
// one-thread backend, so that a run may move between the two
// (cases/bow_shock/backend_switch.hpp); 0 otherwise (a GPU, or Serial alone).
int switchable_host_threads();

}  // namespace granshock

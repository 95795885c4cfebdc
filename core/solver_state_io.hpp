// The state part of the solver interface (core/solver.hpp): the particles and the whole
// solver state out to the host (snapshots, checkpoints) and a checkpoint's state back in.
#pragma once

#include "core/host_particles.hpp"
#include "core/snapshot_part.hpp"
#include "core/solver_state.hpp"

namespace granshock {

class SolverStateIO {
 public:
  virtual ~SolverStateIO() = default;

  virtual HostParticles particles() const = 0;  // copies the owned particles to the host
  // This process's part of a snapshot, with the rows it fills in one process's order
  // (collective; one process: all of them, rows [0, n)).
  virtual SnapshotPart snapshot_part() const = 0;

  // Several processes (docs/parallel.md): export_state is collective and returns the whole
  // state, as one process would hold it, on rank 0 (the scalars alone elsewhere);
  // import_state takes the whole state on every rank, whatever the number of ranks that
  // wrote it.
  virtual SolverState export_state() const = 0;
  // Continues from a checkpoint's state; a state that does not fit this solver (another
  // dimension, unknown species, a neighbour list its positions do not give, ...) is
  // refused with InvalidCheckpoint (core/checkpoint_checks.hpp) before anything changes.
  virtual void import_state(const SolverState& state) = 0;
};

}  // namespace granshock

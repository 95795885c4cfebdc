// How a bow-shock run spreads its output and its threads (docs/parallel.md, "Output";
// docs/benchmarks.md, "A busy machine"), neither of which changes the results, and the
// modes of the collide and study commands; their names are in core/choice_names.hpp.
#pragma once

namespace granshock {

// Several processes: snapshots gathered to rank 0, written by every process at once
// (parallel HDF5), or automatic: collective for large frames (RunFile::collective_pays).
enum class SnapshotOutput { automatic, gathered, collective };

// One process on the host's threads (cases/bow_shock/backend_switch.hpp): automatic moves
// the run to one thread while the threads run slower than one would and back; off keeps
// the threads; alternate moves at every slice (a check that both give the same run).
enum class BackendSwitchMode { automatic, off, alternate };

// One process on several host threads, regions of many steps
// (kernels/solver/thread_shares.hpp): each thread's share of the particles cut by the time
// the threads took before (by_time), equal shares, or moved at every region (alternating:
// a check that the cuts change nothing).
enum class ThreadShareMode { by_time, equal, alternating };

// `granshock collide --along`: the line along which the two bodies approach (values are
// the coordinate index, cases/collision/head_on_collision.hpp).
enum class ImpactLine { x = 0, y = 1 };

// `granshock study --emit`: the batch script written instead of running (docs/study.md,
// "Slurm").
enum class BatchScript { slurm };

}  // namespace granshock

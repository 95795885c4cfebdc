// What a bow-shock run writes while it runs (docs/output_format.md): run.h5 (the time
// series and the particle snapshots, with run.xmf beside it for ParaView), checkpoint.h5,
// and at the end the field sums and summary.json; and what each output cost. Rank 0 writes
// the files; every rank takes part in a snapshot's gather or collective write. A write that
// fails (a full disk, a file-size limit) throws WriteFailed, and what_survives() then says
// whether --resume can continue from what is on disk.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/bow_shock/run_resume.hpp"
#include "core/checkpoint_extras.hpp"
#include "core/communicator.hpp"
#include "core/run_modes.hpp"
#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "io/run_file.hpp"
#include "io/scene_file.hpp"

namespace granshock {

class WriteFailed : public UserError {
 public:
  explicit WriteFailed(const std::string& what) : UserError(what) {}
};

// The wall seconds and counts of the outputs so far (summary.json "processes").
struct OutputCost {
  double snapshot_seconds = 0, checkpoint_seconds = 0;
  long snapshots = 0, checkpoints = 0;
  long collective_snapshots = 0;  // of the snapshots (several processes)
};

class RunOutputs {
 public:
  // `obstacle_outline`: the obstacle's cross-section as run.xmf draws it (empty: none).
  RunOutputs(const Communicator& comm, std::filesystem::path dir, SnapshotOutput snapshots,
             std::vector<std::array<double, 2>> obstacle_outline);

  // Rank 0: a new run.h5.
  void create(const LoadedScene& scene, int dim, const SnapshotContents& contents,
              const std::string& build);
  // Rank 0: the run.h5 `point` continues, cut back to its step, with this leg's scene and
  // extension recorded; returns the extensions the file lists (summary.json "extensions").
  nlohmann::json continue_from(const ResumePoint& point, const LoadedScene& scene);
  // A resumed run's last checkpoint is the one it resumed from.
  void resumed_at(long step) { last_checkpoint_step_ = step; }

  void append_series_row(const TimeSeriesRow& row);  // rank 0
  // Collective: a snapshot of the solver's particles now, and run.xmf made again.
  void write_snapshot(const Solver& solver, long step, double time);
  // Rank 0 writes `state` (with run.h5's record in `extras`); every rank records the step.
  void write_checkpoint(long step, const SolverState& state, CheckpointExtras extras);
  // Rank 0: the field sums into run.h5 and summary.json, at a run's end or stop.
  void write_end(const FieldSumsRecord& sums, const nlohmann::json& summary);
  // Rank 0: closes run.h5, which the field analysis then reads; false where none was open.
  bool close_run_file();

  long last_checkpoint_step() const { return last_checkpoint_step_; }
  const OutputCost& cost() const { return cost_; }
  // After a failed write: whether the last checkpoint and run.h5 still make a run that
  // --resume continues.
  std::string what_survives();

 private:
  const Communicator& comm_;
  const bool root_;
  const std::filesystem::path dir_;
  const SnapshotOutput snapshots_;
  const std::vector<std::array<double, 2>> obstacle_outline_;
  std::optional<RunFile> run_file_;
  RunFileRecord last_record_;  // run.h5 as the last checkpoint recorded it
  long last_checkpoint_step_ = -1;
  OutputCost cost_;
};

}  // namespace granshock

#include "cases/bow_shock/run_outputs.hpp"

#include <fmt/format.h>

#include <chrono>

#include "cases/bow_shock/run_extension.hpp"
#include "core/snapshot_part.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint_file.hpp"
#include "io/xdmf_writer.hpp"
#include "parallel/mpi_communicator.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// Adds the wall time of one output (gather and write) to a total and counts it.
struct OutputTimer {
  double& seconds;
  long& count;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  OutputTimer(double& s, long& n) : seconds(s), count(n) {}
  ~OutputTimer() {
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++count;
  }
};

// A write that failed becomes WriteFailed, for what_survives(). Other errors in the loop
// are said as they are: making room would not help them.
template <class Write>
void writing(Write&& write) {
  try {
    write();
  } catch (const WriteFailed&) {
    throw;
  } catch (const UserError& e) {
    throw WriteFailed(e.what());
  }
}

}  // namespace

RunOutputs::RunOutputs(const Communicator& comm, fs::path dir, SnapshotOutput snapshots,
                       std::vector<std::array<double, 2>> obstacle_outline)
    : comm_(comm),
      root_(comm.is_root()),
      dir_(std::move(dir)),
      snapshots_(snapshots),
      obstacle_outline_(std::move(obstacle_outline)) {}

void RunOutputs::create(const LoadedScene& scene, int dim, const SnapshotContents& contents,
                        const std::string& build) {
  if (!root_) return;
  run_file_.emplace(
      RunFile::create(dir_ / "run.h5", scene.as_given, scene.resolved, dim, contents, build));
}

nlohmann::json RunOutputs::continue_from(const ResumePoint& point, const LoadedScene& scene) {
  if (!root_) return {};
  last_record_ = {point.extras.run_id, point.extras.run_frames, point.extras.run_rows};
  run_file_.emplace(RunFile::open_for_resume(dir_ / "run.h5", point.state.step, last_record_));
  last_record_ = run_file_->record();  // cut back to the checkpoint (and given an id)
  return record_extension(*run_file_, scene.as_given, scene.resolved, point.extension);
}

void RunOutputs::append_series_row(const TimeSeriesRow& row) {
  if (!root_) return;
  writing([&] { run_file_->append_time_series(row); });
}

// Several processes (docs/parallel.md, "Output"): a large frame is written by every
// process at once (parallel HDF5), a small one gathered to rank 0, whichever measured
// faster (RunFile::collective_pays, docs/scaling.md).
void RunOutputs::write_snapshot(const Solver& solver, long step, double time) {
  const OutputTimer timer(cost_.snapshot_seconds, cost_.snapshots);
  const SnapshotPart part = solver.snapshot_part();
  const auto* mpi = dynamic_cast<const MpiCommunicator*>(&comm_);
  const bool collective =
      snapshots_ == SnapshotOutput::collective ||
      (snapshots_ == SnapshotOutput::automatic && RunFile::collective_pays(part.total));
  if (mpi != nullptr && collective) {
    ++cost_.collective_snapshots;
    writing([&] {
      RunFile::append_snapshot_collectively(dir_ / "run.h5", mpi->native(), step, time, part,
                                            run_file_);
    });
  } else {
    const HostParticles frame = gather_snapshot(comm_, part);
    if (root_) writing([&] { run_file_->append_snapshot(step, time, frame); });
  }
  if (!root_) return;
  writing([&] {
    write_particles_xdmf(dir_ / "run.xmf", "run.h5", run_file_->frames(), run_file_->dim(),
                         run_file_->frame_view_arrays(), obstacle_outline_);
  });
}

void RunOutputs::write_checkpoint(long step, const SolverState& state, CheckpointExtras extras) {
  const OutputTimer timer(cost_.checkpoint_seconds, cost_.checkpoints);
  if (root_) {
    writing([&] {
      // run.h5 as this checkpoint continues it: a resume checks it against this record.
      run_file_->flush();
      const RunFileRecord record = run_file_->record();
      extras.run_id = record.run_id;
      extras.run_frames = record.frames;
      extras.run_rows = record.rows;
      granshock::write_checkpoint(dir_ / "checkpoint.h5", state, extras);
      last_record_ = record;
    });
  }
  // After the write: a failed one leaves the last good checkpoint's step for the message.
  last_checkpoint_step_ = step;
}

void RunOutputs::write_end(const FieldSumsRecord& sums, const nlohmann::json& summary) {
  if (!root_) return;
  writing([&] {
    write_field_sums(*run_file_, sums);
    run_file_->flush();
    write_file_atomically(dir_ / "summary.json", summary.dump(2) + "\n");
  });
}

bool RunOutputs::close_run_file() {
  if (!run_file_) return false;
  run_file_.reset();
  return true;
}

// Rank 0, which wrote them, says it.
std::string RunOutputs::what_survives() {
  if (last_checkpoint_step_ < 0)
    return "no checkpoint had been written yet: make room and start again with --overwrite";
  const std::string resume =
      fmt::format("checkpoint.h5 (step {}) is intact: make room and continue with --resume",
                  last_checkpoint_step_);
  if (!root_ || !run_file_) return resume;
  // run.h5 reserves room before every change (io/run_file.hpp), so a failed write leaves it
  // as it was; checked all the same, as the resume will check it.
  try {
    run_file_.reset();
    RunFile::check_resumable(dir_ / "run.h5", last_checkpoint_step_, last_record_);
  } catch (const std::exception&) {
    return fmt::format(
        "checkpoint.h5 (step {}) is intact, but the failed write damaged run.h5, so the run "
        "cannot be resumed: make room and start again with --overwrite",
        last_checkpoint_step_);
  }
  return resume;
}

}  // namespace granshock

// One bow-shock run (docs/design.md, "The bow-shock case"): the scene's checks, the run
// directory, the solver, the inflow and the field sampling, driven step by step to the
// end, a signal or --stop-after-steps, with the outputs of docs/output_format.md at their
// intervals (time series, snapshots, checkpoints) and the summary and field analysis at
// the end. On several processes (docs/parallel.md) every rank runs this same loop over
// its slab; global quantities go through the Communicator and rank 0 alone writes.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/bow_shock/backend_mover.hpp"
#include "cases/bow_shock/inflow.hpp"
#include "cases/bow_shock/prepared_scene.hpp"
#include "cases/bow_shock/progress_meter.hpp"
#include "cases/bow_shock/run_log.hpp"
#include "cases/bow_shock/run_options.hpp"
#include "cases/bow_shock/run_outputs.hpp"
#include "cases/bow_shock/run_resume.hpp"
#include "cases/bow_shock/sampling_plan.hpp"
#include "cases/bow_shock/thermo_table.hpp"
#include "core/communicator.hpp"
#include "core/solver.hpp"
#include "io/run_directory.hpp"
#include "io/scene_file.hpp"
#include "kernels/device/launch_counter.hpp"

namespace granshock {

class BowShockRun {
 public:
  BowShockRun(const RunOptions& options, LoadedScene loaded,
              const Communicator& comm = SingleProcess::instance());
  // The process exit code (run_command.hpp).
  int execute();

 private:
  struct Schedule {
    long every;
    bool due(long step) const { return every > 0 && step % every == 0; }
    long next_after(long step) const { return (step / every + 1) * every; }
  };

  int execute_or_throw();
  void prepare();
  void open_run_file();
  int advance_to_end();
  void analyse();
  std::string interrupted_message(int signal) const;
  std::string resume_command() const;
  long agreed_next_step(long step);
  void start_fresh();
  void resume();
  nlohmann::json processes_summary() const;
  void actions_at(long step);
  void write_series_row(long step);
  void report_thermo(long step);
  TimeSeriesRow observe(long step, Diagnostics* diagnostics = nullptr);
  void write_snapshot(long step);
  // CPU seconds of every leg so far, all processes (collective); -1 where not known.
  double cpu_seconds_so_far() const;
  void write_checkpoint_now();
  void finish(bool completed);
  void warn_if_inflow_falls_short();
  std::string inflow_note() const;
  void advance_slice(long steps);
  std::unique_ptr<Solver> make_run_solver(Backend backend, std::size_t capacity) const;

  const RunOptions& options_;
  const Communicator& comm_;
  const bool root_;    // rank 0: writes the files and speaks
  RunLog log_;         // stderr and log.txt (rank 0's)
  ThermoFile thermo_;  // thermo.txt (rank 0's)
  long last_thermo_step_ = -1;
  LaunchCounter launches_;  // over the time loop of this leg
  LoadedScene given_;       // the scene as loaded, until prepare() makes prepared_ of it
  // The scene this run runs, checked and calibrated once (prepared_scene.hpp), and what
  // follows from it; set by prepare() and not changed after.
  std::optional<const PreparedScene> prepared_;
  const Scene& scene() const { return prepared_->scene(); }
  std::filesystem::path dir_;
  DirectoryMode mode_ = DirectoryMode::create;
  std::optional<ResumePoint> resume_point_;  // --resume: read and checked (run_resume.hpp)
  std::optional<InflowController> inflow_;
  std::optional<SamplingPlan> sampling_;
  std::unique_ptr<Solver> solver_;
  Decomposition decomposition_;
  BackendMover backends_;              // threads or one thread (backend_mover.hpp)
  std::optional<RunOutputs> outputs_;  // run.h5, checkpoint.h5, summary.json (run_outputs.hpp)
  Schedule series_{1}, snapshots_{1}, checkpoints_{1};
  long total_steps_ = 0, first_step_ = 0;
  double wall_before_ = 0;       // wall seconds of earlier legs (resumed runs)
  double cpu_before_ = 0;        // CPU seconds of earlier legs, all processes; -1: not known
  double cpu_at_leg_start_ = 0;  // this process's CPU clock when the time loop started
  double particle_steps_ = 0;    // particle-steps of this leg
  EarlierSummary earlier_;       // --resume: what the summary.json of the earlier legs said
  std::vector<long> samples_;    // field samples per block
  nlohmann::json extensions_;    // --resume: every extension run.h5 lists (summary.json)
  bool claimed_ = false;         // the directory is the run's (marked, cleaned)
  std::optional<ProgressMeter> meter_;
  std::optional<RunDirectory> run_directory_;
  bool warned_inflow_ = false;
  bool warned_backflow_ = false;  // particles leaving through the inlet (run_observables.hpp)
  bool warned_energy_ = false;    // energy created by the integration (run_observables.hpp)
};

}  // namespace granshock

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
#include "cases/bow_shock/inlet_calibration.hpp"
#include "cases/bow_shock/progress_meter.hpp"
#include "cases/bow_shock/run_extension.hpp"
#include "cases/bow_shock/run_log.hpp"
#include "cases/bow_shock/run_options.hpp"
#include "cases/bow_shock/sampling_plan.hpp"
#include "cases/bow_shock/thermo_table.hpp"
#include "core/checkpoint_extras.hpp"
#include "core/communicator.hpp"
#include "core/solver.hpp"
#include "io/run_directory.hpp"
#include "io/run_file.hpp"
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
  std::string what_survives();
  void analyse();
  std::string interrupted_message(int signal) const;
  std::string resume_command() const;
  long agreed_next_step(long step);
  bool calibrate_inflow();       // true when it changed sigma (inflow.mach_at = "inlet_bins")
  bool calibrate_restitution();  // true when it set the damping (restitution_mode = "discrete")
  void start_fresh();
  void read_checkpoint_and_check();
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
  void read_earlier_summary();
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
  LoadedScene loaded_;
  const Scene& scene_;
  std::filesystem::path dir_;
  DirectoryMode mode_ = DirectoryMode::create;
  SolverState checkpoint_state_;  // --resume: read and checked, until the solver takes it
  CheckpointExtras checkpoint_extras_;
  InflowController inflow_;
  SamplingPlan sampling_;
  std::unique_ptr<Solver> solver_;
  Decomposition decomposition_;
  BackendMover backends_;  // threads or one thread (backend_mover.hpp)
  std::optional<RunFile> run_file_;
  Schedule series_{1}, snapshots_{1}, checkpoints_{1};
  long total_steps_ = 0, first_step_ = 0;
  double wall_before_ = 0;       // wall seconds of earlier legs (resumed runs)
  double cpu_before_ = 0;        // CPU seconds of earlier legs, all processes; -1: not known
  double cpu_at_leg_start_ = 0;  // this process's CPU clock when the time loop started
  double particle_steps_ = 0;    // particle-steps of this leg
  // --resume: what the summary.json of the earlier legs said (null where it said nothing).
  nlohmann::json earlier_warnings_, earlier_rate_;
  std::vector<long> samples_;  // field samples per block
  // --resume: what this leg changes of the checkpoint's time keys, and every extension
  // run.h5 lists (summary.json "extensions").
  RunExtension extension_;
  nlohmann::json extensions_;
  long last_checkpoint_step_ = -1;
  RunFileRecord last_record_;  // run.h5 as the last checkpoint recorded it
  bool claimed_ = false;       // the directory is the run's (marked, cleaned)
  std::optional<ProgressMeter> meter_;
  std::optional<RunDirectory> run_directory_;
  bool warned_inflow_ = false;
  bool warned_backflow_ = false;  // particles leaving through the inlet (run_observables.hpp)
  bool warned_energy_ = false;    // energy created by the integration (run_observables.hpp)
  std::optional<InletCalibration> calibration_;
  struct OutputCost {
    double snapshot_seconds = 0, checkpoint_seconds = 0;
    long snapshots = 0, checkpoints = 0;
    long collective_snapshots = 0;  // of the snapshots (several processes)
  } output_;
};

}  // namespace granshock

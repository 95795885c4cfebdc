#include "cases/bow_shock/bow_shock_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <iostream>

#include "analysis/figure_switch.hpp"
#include "analysis/run_analysis.hpp"
#include "cases/accuracy/accuracy_choice.hpp"
#include "cases/bow_shock/interrupt.hpp"
#include "cases/bow_shock/run_extension.hpp"
#include "cases/bow_shock/run_observables.hpp"
#include "cases/bow_shock/run_resume.hpp"
#include "cases/bow_shock/run_state.hpp"
#include "cases/bow_shock/run_summary.hpp"
#include "cases/build_info/build_description.hpp"
#include "core/choice_names.hpp"
#include "core/failure_agreement.hpp"
#include "core/process_clock.hpp"
#include "core/shell_text.hpp"
#include "core/user_error.hpp"
#include "io/field_sums_file.hpp"
#include "kernels/device/launch_counter.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// The obstacle's cross-section as run.xmf shows it (none without an obstacle).
std::vector<std::array<double, 2>> obstacle_polygon(const Scene& scene) {
  if (!scene.setup.obstacle) return {};
  const Obstacle& o = *scene.setup.obstacle;
  return outline_points(obstacle_outline(o), o.centre[0], o.centre[1]);
}

std::string signal_name(int signal) {
  return signal == SIGINT    ? "SIGINT"
         : signal == SIGTERM ? "SIGTERM"
                             : fmt::format("signal {}", signal);
}

// Intervals longer than the run act once, at its end: clamping them to the duration keeps
// the step count in range (run_checks.hpp bounds duration / dt).
long every_seconds(double interval, double duration, double dt) {
  return std::max(1L, long(std::llround(std::min(interval, duration) / dt)));
}

}  // namespace

BowShockRun::BowShockRun(const RunOptions& o, LoadedScene loaded, const Communicator& comm)
    : options_(o),
      comm_(comm),
      root_(comm.is_root()),
      log_(root_),
      given_(std::move(loaded)),
      backends_(o.backend_switch, o.quiet, log_) {}

int BowShockRun::execute() {
  // Held since the program started (apps/granshock/main.cpp); in-process callers start here.
  catch_interrupts();
  try {
    return execute_or_throw();
  } catch (const Interrupted& e) {
    // The rank that reports an agreed failure, or rank 0 where every rank stopped alike.
    if (root_)
      log_.say(interrupted_message(e.signal()));
    else if (failure_agreed())
      std::cerr << interrupted_message(e.signal()) << "\n";
    return e.exit_code();
  } catch (const PeerFailed&) {
    throw;  // said by the rank that failed
  } catch (const NumericalFailure& e) {
    log_.record(std::string("granshock: error: ") + e.what());  // said by main()
    throw;
  } catch (const UserError& e) {
    log_.record(std::string("granshock: error: ") + e.what());
    throw;
  } catch (const std::exception& e) {
    log_.record(std::string("granshock: internal error: ") + e.what());
    throw;
  }
}

// The command that continues this run: its checkpoint keeps the scene with every --set of
// its legs, so the scene file and the directory say it all (docs/output_format.md,
// "Resuming").
std::string BowShockRun::resume_command() const {
  return fmt::format("granshock run {} --out {} --resume",
                     shell_quote(options_.scene_file.string()), shell_quote(dir_.string()));
}

// Before the first checkpoint (docs/output_format.md, "Signals").
std::string BowShockRun::interrupted_message(int signal) const {
  if (!claimed_)
    return fmt::format(
        "granshock: interrupted by {} while setting up the run, before anything was written "
        "to '{}'; run the same command again",
        signal_name(signal), dir_.string());
  return fmt::format(
      "granshock: interrupted by {} before the first checkpoint (while prefilling the "
      "domain); '{}' holds no checkpoint to resume: start again with --overwrite",
      signal_name(signal), dir_.string());
}

int BowShockRun::execute_or_throw() {
  // The log's first line: what ran, and which program (log.txt of every leg).
  log_.record(fmt::format("{}: run {} {}{} on {} process{}", version_line(),
                          options_.scene_file.string(),
                          options_.resume      ? "(--resume)"
                          : options_.overwrite ? "(--overwrite)"
                                               : "(new)",
                          options_.overrides.empty()
                              ? std::string()
                              : fmt::format(" --set {}", fmt::join(options_.overrides, " --set ")),
                          comm_.size(), comm_.size() == 1 ? "" : "es"));
  // Failures up to here are the same on every rank, or rank 0's alone (its directory and
  // files): all ranks agree on them before the first collective step (docs/parallel.md,
  // "Errors"). No step inside an agreement may itself be collective: a rank that failed
  // before it would meet the agreement's reduction instead.
  agree_on_failure(comm_, [&] { prepare(); });
  agree_on_failure(comm_, [&] {
    throw_if_interrupted();
    // Every check of the scene is done: from here on the run holds the directory's lock. A
    // resume reads and checks the checkpoint under it before it changes anything, so that a
    // refused --resume leaves the directory as it was (the marker, the temporaries).
    if (root_ && options_.resume) run_directory_.emplace(RunDirectory::hold(dir_, mode_));
    if (options_.resume)
      resume_point_.emplace(read_resume_point(dir_, prepared_->loaded, *inflow_));
    if (root_ && !options_.resume) run_directory_.emplace(RunDirectory::claim(dir_, mode_));
    if (root_ && options_.resume) {
      RunFile::check_resumable(dir_ / "run.h5", resume_point_->state.step,
                               {resume_point_->extras.run_id, resume_point_->extras.run_frames,
                                resume_point_->extras.run_rows});
      run_directory_->settle();
    }
    claimed_ = true;
    open_run_file();
  });
  if (options_.resume) agree_on_failure(comm_, [&] { resume(); });
  // The log once the run is accepted: a refused --resume leaves the directory as it was.
  agree_on_failure(comm_, [&] {
    log_.open(dir_);
    if (root_)
      thermo_.open(dir_,
                   fmt::format("{}: {} from step {}", version_line(),
                               options_.resume ? "--resume" : "new run", solver_->steps_done()));
    if (options_.resume && root_) earlier_ = read_earlier_summary(dir_);
    if (options_.resume && resume_point_->extension.changes()) {
      if (options_.quiet)
        log_.record(extension_note(resume_point_->extension));
      else
        log_.say(extension_note(resume_point_->extension));
    }
  });
  try {
    if (!options_.resume) start_fresh();  // writes the outputs of step 0
    first_step_ = solver_->steps_done();
    cpu_at_leg_start_ = process_cpu_seconds();
    meter_.emplace(first_step_, total_steps_, scene().run.progress_interval_s,
                   [this](const std::string& line) {
                     if (options_.quiet)
                       log_.record(line);
                     else
                       log_.say(line);
                   });
    return advance_to_end();
  } catch (const WriteFailed& e) {
    throw UserError(fmt::format("{}; {}", e.what(), outputs_->what_survives()));
  }
}

// The scene's checks and calibrations (prepared_scene.hpp), the directory's check and the
// solver.
void BowShockRun::prepare() {
  dir_ = run_directory_of(options_, given_.scene);
  throw_if_interrupted();
  mode_ = options_.resume      ? DirectoryMode::resume
          : options_.overwrite ? DirectoryMode::overwrite
                               : DirectoryMode::create;
  PrepareOptions how;
  how.force = options_.force;
  how.processes = comm_.size();
  how.certified = certified_step(options_.accuracy_choice);
  if (!options_.quiet) how.say = [this](const std::string& line) { log_.say(line); };
  how.checked = [this] {
    // Rank 0's alone: probing the lock from several ranks at once would see each other.
    if (root_) RunDirectory::check(dir_, mode_);
    backends_.choose_start(comm_.size());
    return backends_.backend();
  };
  prepared_.emplace(prepare_scene(std::move(given_), how));
  for (const std::string& w : prepared_->warnings) log_.warn(w);
  inflow_.emplace(scene());
  sampling_.emplace(scene());
  outputs_.emplace(comm_, dir_, options_.snapshot_output, obstacle_polygon(scene()));

  throw_if_interrupted();
  total_steps_ = scene().total_steps();
  series_.every =
      every_seconds(scene().run.series_interval_s, scene().run.duration_s, scene().setup.dt);
  snapshots_.every =
      every_seconds(scene().run.snapshot_interval_s, scene().run.duration_s, scene().setup.dt);
  checkpoints_.every =
      every_seconds(scene().run.checkpoint_interval_s, scene().run.duration_s, scene().setup.dt);
  decomposition_.axis = options_.slabs;
  decomposition_.balance = options_.balance;
  solver_ = make_run_solver(backends_.backend(), scene().capacity_estimate());
  samples_.assign(std::size_t(sampling_->blocks()), 0);
}

// Rank 0's run.h5: a new one, or the one a checkpoint continues.
void BowShockRun::open_run_file() {
  if (options_.resume) {
    extensions_ = outputs_->continue_from(*resume_point_, prepared_->loaded);
    return;
  }
  SnapshotContents contents;
  for (const Species& s : scene().setup.species) contents.species_radius.push_back(s.radius_m());
  contents.angular_velocity = scene().setup.contacts.has_friction();
  outputs_->create(prepared_->loaded, scene().setup.dim, contents, build_description().dump());
}

// The time loop from the current step to the end, a signal or --stop-after-steps.
int BowShockRun::advance_to_end() {
  long step = first_step_;
  launches_.start();  // what the time loop costs beyond arithmetic (summary.json)
  while (step < total_steps_) {
    // Advance to the next event (insertion, output) or a slice of about 0.25 s of wall
    // time, so that progress and signals are answered promptly (or of --slice-steps).
    const long slice = options_.slice_steps > 0 ? options_.slice_steps
                                                : meter_->steps_per(backends_.slice_seconds(), 50);
    long next = std::min(total_steps_, step + slice);
    next = std::min(next, (step / inflow_->period_steps() + 1) * inflow_->period_steps());
    for (const Schedule* s : {&series_, &snapshots_, &checkpoints_})
      next = std::min(next, s->next_after(step));
    next = std::min(next, sampling_->next_after(step));
    if (options_.stop_after_steps > 0)
      next = std::min(next, first_step_ + options_.stop_after_steps);
    next = agreed_next_step(next);
    advance_slice(next - step);
    step = next;
    meter_->observe(step);
    actions_at(step);
    warn_if_inflow_falls_short();
    // Collective: every rank takes part in the counts rank 0 reports. Rank 0's clock alone
    // says when: the other ranks' meters never report, so they would be due at every slice.
    // A --quiet run shows nothing but keeps its thermo table.
    if (comm_.any(root_ && meter_->due())) report_thermo(step);
    // A signal reaches the ranks at different moments: the highest one seen stops all.
    const int signal = int(comm_.max(double(interrupt_signal())));
    if (signal != 0) {
      write_checkpoint_now();
      report_thermo(step);
      finish(false);
      log_.say(
          fmt::format("granshock: interrupted at step {}; checkpoint written, continue with "
                      "--resume: {}",
                      step, resume_command()));
      return 128 + signal;
    }
    backends_.move_if_due(
        solver_, scene().capacity_estimate(),
        [this](Backend b, std::size_t capacity) { return make_run_solver(b, capacity); });
    if (options_.stop_after_steps > 0 && step >= first_step_ + options_.stop_after_steps &&
        step < total_steps_) {
      write_checkpoint_now();
      report_thermo(step);
      finish(false);
      log_.say(
          fmt::format("granshock: stopped after {} steps at step {}; continue with --resume: {}",
                      options_.stop_after_steps, step, resume_command()));
      return 0;
    }
  }
  report_thermo(step);
  finish(true);
  return 0;
}

// The slices end where the wall clock says (ProgressMeter::steps_per), which differs from
// rank to rank: all take the earliest end.
long BowShockRun::agreed_next_step(long step) {
  return long(-comm_.max(-double(step)));
}

void BowShockRun::start_fresh() {
  solver_->set_particles(HostParticles{});
  // A large prefill takes minutes: its progress, in the run's form (progress_meter.hpp),
  // and a signal stops it between slabs, on every rank at the same slab (the insertion is
  // collective).
  ProgressMeter prefill(0, 0, scene().run.progress_interval_s,
                        [this](const std::string& line) { log_.say(line); });
  inflow_->prefill(*solver_, [&](long done, long slabs) {
    if (const int signal = int(comm_.max(double(interrupt_signal()))); signal != 0)
      throw Interrupted(signal);
    if (root_ && !options_.quiet && prefill.due())
      prefill.report_prefill(done, slabs, long(inflow_->inserted()));
  });
  actions_at(0);
}

// Everything is checked before anything changes: a refused checkpoint leaves the run
// directory as it was (run_resume.hpp).
void BowShockRun::resume() {
  wall_before_ = resume_point_->extras.wall_seconds_so_far;
  cpu_before_ = resume_point_->extras.cpu_seconds_so_far;
  outputs_->resumed_at(resume_point_->state.step);
  resume_from(*resume_point_, dir_, *solver_, *inflow_, samples_);
}

// Everything that happens at a step boundary, in a fixed order (a checkpoint at step s
// is taken after the insertion and outputs of step s, and a resumed run starts after them).
void BowShockRun::actions_at(long step) {
  inflow_->insert_if_due(*solver_, step);
  if (sampling_->due(step)) {
    const int block = sampling_->block_of(step);
    solver_->sample_fields(block);
    ++samples_[block];
  }
  if (series_.due(step) || step == total_steps_) write_series_row(step);
  if (snapshots_.due(step) || step == total_steps_) write_snapshot(step);
  if (checkpoints_.due(step) || step == total_steps_) write_checkpoint_now();
}

// Collective: every rank takes part in the sums; rank 0 shows the row (not with --quiet:
// log.txt alone) and appends it to thermo.txt (thermo_table.hpp).
void BowShockRun::report_thermo(long step) {
  const TimeSeriesRow row = observe(step);
  if (!root_ || step == last_thermo_step_) return;  // the last report was at this step
  last_thermo_step_ = step;
  thermo_.append(meter_->report(thermo_row(row), particle_steps_, inflow_note()));
}

// Collective: the time-series row of the run's state now (global sums); `diagnostics`
// receives the solver's, for the health check.
TimeSeriesRow BowShockRun::observe(long step, Diagnostics* diagnostics) {
  const Diagnostics d = solver_->diagnostics();
  const RemovalCounts removed = solver_->removed();
  TimeSeriesRow row;
  row.step = step;
  row.time = step * scene().setup.dt;
  row.particles = solver_->global_size();
  row.kinetic_energy = d.kinetic_energy + d.rotational_energy;
  row.temperature = mixture_temperature(scene(), solver_->species_moments());
  row.contacts = d.contacts;
  row.inserted = inflow_->inserted();
  row.deleted_outlet = removed.high[1];
  row.deleted_inlet = removed.low[1];
  if (diagnostics) *diagnostics = d;
  return row;
}

// Collective: every rank forms the row (global sums), rank 0 writes it.
void BowShockRun::write_series_row(long step) {
  Diagnostics d;
  const TimeSeriesRow row = observe(step, &d);
  check_health(scene(), step, d, std::size_t(row.particles));
  if (!root_) return;
  outputs_->append_series_row(row);
  if (!warned_energy_) {
    const std::string energy =
        energy_warning(scene(), row.kinetic_energy, std::size_t(row.particles), row.time);
    warned_energy_ = !energy.empty();
    if (warned_energy_) log_.warn(energy);
  }
  if (!warned_backflow_) {
    const std::string backflow = inlet_backflow_warning(row.deleted_inlet, row.inserted, row.time);
    warned_backflow_ = !backflow.empty();
    if (warned_backflow_) log_.warn(backflow);
  }
}

void BowShockRun::write_snapshot(long step) {
  outputs_->write_snapshot(*solver_, step, step * scene().setup.dt);
}

double BowShockRun::cpu_seconds_so_far() const {
  const double leg = comm_.sum(process_cpu_seconds() - cpu_at_leg_start_);
  return cpu_before_ >= 0 ? cpu_before_ + leg : -1.0;
}

void BowShockRun::write_checkpoint_now() {
  const long step = solver_->steps_done();
  if (step == outputs_->last_checkpoint_step()) return;
  const double wall = wall_before_ + (meter_ ? meter_->elapsed_s() : 0.0);
  CheckpointExtras extras = pack_run_state(prepared_->loaded.resolved, *solver_, *inflow_, samples_,
                                           wall, cpu_seconds_so_far());
  extras.scene_overrides = options_.overrides;  // with --resume, every leg's (run_command.hpp)
  outputs_->write_checkpoint(step, solver_->export_state(), std::move(extras));
}

void BowShockRun::finish(bool completed) {
  FieldSumsRecord sums;
  sums.sampling = sampling_->layout();
  sums.grid_sums = solver_->field_sums(false);
  if (sums.sampling.has_profile()) sums.profile_sums = solver_->field_sums(true);
  sums.samples = samples_;
  sums.production_start = scene().run.production_start_s;
  sums.production_end = scene().run.duration_s;
  sums.sample_every = scene().run.sample_every;
  sums.y_end = scene().setup.box.hi[1];
  const double wall = wall_before_ + meter_->elapsed_s();
  const long steps = solver_->steps_done();
  const bool counted = launches_.running();
  const LaunchCounts launched = launches_.stop();
  nlohmann::json j =
      run_summary(scene(), *solver_, *inflow_, prepared_->inlet ? &*prepared_->inlet : nullptr,
                  completed, {wall, cpu_seconds_so_far(), meter_->elapsed_s(), particle_steps_});
  // Several processes: how the work was shared (one process: nothing to say).
  if (comm_.size() > 1) j["processes"] = processes_summary();
  if (const nlohmann::json moves = backends_.summary(); !moves.is_null())
    j["backend_switch"] = moves;
  // One process on several threads: how they shared the particles (docs/benchmarks.md,
  // "Threads on a small scene").
  if (const ThreadShareStats shares = solver_->thread_shares(); shares.shares.size() > 1)
    j["thread_shares"] = {{"mode", choice_name(options_.thread_shares)},
                          {"shares", shares.shares},
                          {"moves", shares.moves},
                          {"last_imbalance", shares.imbalance}};
  // Per step of this leg's time loop, this process' (docs/cuda.md, "Launches per step");
  // null where a profiling tool held Kokkos' hooks or no step ran, and fences where this
  // Kokkos does not report them (3.4).
  const long looped = steps - first_step_;
  const auto per_step = [&](std::uint64_t n) {
    return counted && looped > 0 ? nlohmann::json(double(n) / double(looped)) : nlohmann::json();
  };
  j["kernel_launches_per_step"] = per_step(launched.kernels);
  j["fences_per_step"] = launched.fences_reported ? per_step(launched.fences) : nlohmann::json();
  j["device_to_host_copies_per_step"] = per_step(launched.device_to_host_copies);
  j["deep_copies_per_step"] = per_step(launched.deep_copies);
  j["reductions_per_step"] = per_step(launched.reductions);
  j["host_reads_per_step"] = per_step(launched.host_reads);
  if (!root_) return;
  if (!options_.accuracy_choice.is_null()) j["accuracy_choice"] = options_.accuracy_choice;
  if (!extensions_.empty()) j["extensions"] = extensions_;
  // A leg that ran no step (--resume of a completed run) measured no rate: the earlier
  // leg's stays.
  if (particle_steps_ == 0 && earlier_.rate.is_number())
    j["particle_steps_per_second"] = earlier_.rate;
  // Every leg's warnings (docs/stability.md), the earlier legs' first.
  nlohmann::json warnings =
      earlier_.warnings.is_array() ? earlier_.warnings : nlohmann::json::array();
  for (const std::string& w : log_.warnings())
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  j["warnings"] = warnings;
  outputs_->write_end(sums, j);
  // The field analysis reads run.h5, which must be closed first.
  if (completed && outputs_->close_run_file() && run_has_field_sums(dir_)) analyse();
  const std::string done = fmt::format(
      "granshock: {} done: {} steps, {:.4g} s simulated in {:.1f} s wall, {:.3g} "
      "particle-steps/s, {} particles at the end; results in {}",
      scene().name, steps, steps * scene().setup.dt, wall,
      j["particle_steps_per_second"].get<double>(), j["particles_final"].get<long>(),
      dir_.string());
  if (completed) log_.record(done);
  if (completed && !options_.quiet) std::cout << done << "\n";
}

// The field analysis of a completed run (`granshock fields`): the run's data is complete,
// so neither a failure nor a signal here calls for --resume.
void BowShockRun::analyse() {
  const std::string complete = fmt::format(
      "the run's data is complete (checkpoint.h5, run.h5, summary.json): `granshock fields {}` "
      "redoes the analysis",
      dir_.string());
  const ExitAtInterrupt at_signal("granshock: interrupted during the field analysis; " + complete);
  try {
    // In the run's directory, under the lock this run holds (run_directory_).
    const AnalysedRun done = analyse_finished_run(
        dir_, options_.figures, [this](const std::string& line) { log_.say(line); });
    if (!options_.quiet) std::cout << done.result_line() << "\n";
  } catch (const UserError& e) {
    throw UserError(fmt::format("{}; {}", e.what(), complete));
  }
  if (!options_.figures && !options_.quiet)
    log_.say(figures_skipped_note({"granshock", "fields", dir_.string()}));
}

// One slice of the time loop, timed for the choice between threads and one thread.
void BowShockRun::advance_slice(long steps) {
  const double particle_steps = double(solver_->global_size()) * double(steps);
  particle_steps_ += particle_steps;
  backends_.advance(*solver_, steps, particle_steps);
}

// A new solver on `backend`, set up as this run's, without particles.
std::unique_ptr<Solver> BowShockRun::make_run_solver(Backend backend, std::size_t capacity) const {
  SolverSetup setup = scene().setup;
  setup.thread_shares = options_.thread_shares;
  std::unique_ptr<Solver> solver = make_solver(setup, capacity, backend, &comm_);
  solver->configure_sampling(sampling_->layout());
  solver->decompose(decomposition_);
  return solver;
}

// summary.json "processes": how many, and the particles each rank owns at the end (the
// load balance of the slabs; collective).
nlohmann::json BowShockRun::processes_summary() const {
  const HaloStats halo = solver_->halo_stats();
  const double wall = meter_->elapsed_s();
  const OutputCost& cost = outputs_->cost();
  return {{"count", comm_.size()},
          {"slabs_along", choice_name(options_.slabs)},
          {"balance", choice_name(options_.balance)},
          {"particles_per_rank", gather_to_root(comm_, long(solver_->size()))},
          {"ghosts_per_rank", gather_to_root(comm_, halo.ghosts)},
          {"halo_share_per_rank", gather_to_root(comm_, wall > 0 ? halo.seconds / wall : 0.0)},
          {"rebuild_exchange_share_per_rank",
           gather_to_root(comm_, wall > 0 ? halo.rebuild_seconds / wall : 0.0)},
          {"sync_share_per_rank", gather_to_root(comm_, wall > 0 ? halo.sync_seconds / wall : 0.0)},
          {"halo_bytes_sent_per_rank", gather_to_root(comm_, halo.bytes_sent)},
          {"rebalances", halo.rebalances},
          {"migrated_per_rank", gather_to_root(comm_, halo.migrated)},
          // Output (docs/scaling.md): how snapshots were written, and rank 0's seconds per
          // snapshot (either way) and per checkpoint (gathered to rank 0, written there).
          {"snapshot_output", choice_name(options_.snapshot_output)},
          {"snapshots_written_collectively", cost.collective_snapshots},
          {"snapshot_seconds_each",
           cost.snapshots > 0 ? cost.snapshot_seconds / double(cost.snapshots) : 0.0},
          {"checkpoint_seconds_each",
           cost.checkpoints > 0 ? cost.checkpoint_seconds / double(cost.checkpoints) : 0.0}};
}

// docs/scene_format.md, "The inflow": a strip that cannot take what the inflow asks for
// (area fraction near the insertion limit, a shock reaching the inlet) is reported, once,
// as soon as the shortfall passes InflowController::kShortfallWarning.
void BowShockRun::warn_if_inflow_falls_short() {
  if (warned_inflow_ || !inflow_->falls_short()) return;
  warned_inflow_ = true;
  log_.warn(fmt::format(
      "the inflow falls short: {:.0f} of {:.0f} requested particles ({:.1f}%) found no room "
      "in the insertion strip by t = {:.4g} s; phi_inf will be below its target {:g} "
      "(summary.json: inflow)",
      inflow_->shortfall(), inflow_->requested(), 100 * inflow_->shortfall() / inflow_->requested(),
      solver_->time(), scene().inflow.area_fraction));
}

std::string BowShockRun::inflow_note() const {
  if (inflow_->shortfall() < 1.0) return {};
  return fmt::format("inflow short by {:.0f} ({:.1f}%, backlog {:.0f})", inflow_->shortfall(),
                     100 * inflow_->shortfall() / inflow_->requested(), inflow_->backlog());
}

}  // namespace granshock

#include "run_command.hpp"

#include <fmt/format.h>
#include <Kokkos_Core.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <iostream>
#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#include "checkpoint_checks.hpp"
#include "checkpoint_file.hpp"
#include "fields_command.hpp"
#include "head_on_collision.hpp"
#include "inflow.hpp"
#include "progress_meter.hpp"
#include "run_checks.hpp"
#include "run_directory.hpp"
#include "run_file.hpp"
#include "scene_file.hpp"
#include "solver.hpp"
#include "user_error.hpp"
#include "xdmf_writer.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) {
  g_signal = sig;
}

// Mixture granular temperature of the whole domain (DESIGN.md 2.3 applied to all
// particles at once): T_a = m_a <|c - u|^2> / Dim about the mass-averaged velocity u,
// T = sum_a xi_a T_a.
double mixture_temperature(const Scene& s, const std::vector<SpeciesMoments>& mom) {
  const int dim = s.setup.dim;
  double mass = 0, count = 0;
  std::array<double, 3> momentum{0, 0, 0};
  for (std::size_t a = 0; a < mom.size(); ++a) {
    const double m = s.setup.species[a].mass_kg();
    mass += m * mom[a].count;
    count += mom[a].count;
    for (int c = 0; c < dim; ++c) momentum[c] += m * mom[a].velocity_sum[c];
  }
  if (count == 0) return 0;
  double t = 0;
  for (std::size_t a = 0; a < mom.size(); ++a) {
    if (mom[a].count == 0) continue;
    const double m = s.setup.species[a].mass_kg();
    double fluct = mom[a].speed_squared_sum;  // sum |c - u|^2 = sum c^2 - 2 u.sum c + N u^2
    for (int c = 0; c < dim; ++c) {
      const double u = momentum[c] / mass;
      fluct += -2 * u * mom[a].velocity_sum[c] + mom[a].count * u * u;
    }
    t += (mom[a].count / count) * m * fluct / (dim * mom[a].count);
  }
  return t;
}

struct Schedule {
  long every;
  bool due(long step) const { return every > 0 && step % every == 0; }
  long next_after(long step) const { return (step / every + 1) * every; }
};

// Intervals longer than the run act once, at its end: clamping them to the duration keeps
// the step count in range (run_checks.hpp bounds duration / dt).
Schedule every_seconds(double interval, double duration, double dt) {
  return {std::max(1L, long(std::llround(std::min(interval, duration) / dt)))};
}

fs::path run_directory_of(const RunOptions& o, const Scene& scene) {
  return o.out_dir.empty() ? fs::path("runs") / scene.name : o.out_dir;
}

class BowShockRun {
 public:
  BowShockRun(const RunOptions& o, LoadedScene loaded)
      : options_(o), loaded_(std::move(loaded)), scene_(loaded_.scene), inflow_(scene_) {}

  int execute();
  int advance_to_end();

 private:
  void start_fresh();
  void resume();
  void actions_at(long step);
  void write_series_row(long step);
  void write_snapshot(long step);
  void write_checkpoint_now();
  void finish(bool completed);
  void configure_sampling();
  bool sample_due(long step) const;
  int block_of(long step) const;
  long next_sample_after(long step) const;
  RunFit run_fit(long step) const;
  double inflow_energy() const;
  void write_field_sums();
  void check_health(long step, const Diagnostics& d) const;
  void warn_if_inflow_falls_short();
  std::string inflow_note() const;
  nlohmann::json inflow_summary() const;
  nlohmann::json restitution_at_dt() const;

  const RunOptions& options_;
  LoadedScene loaded_;
  const Scene& scene_;
  fs::path dir_;
  InflowController inflow_;
  std::unique_ptr<Solver> solver_;
  std::optional<RunFile> run_file_;
  Schedule series_{1}, snapshots_{1}, checkpoints_{1};
  long total_steps_ = 0, first_step_ = 0;
  double wall_before_ = 0;     // wall seconds of earlier legs (resumed runs)
  double particle_steps_ = 0;  // particle-steps of this leg
  FieldSampling sampling_;
  long production_first_step_ = 0;
  std::vector<long> samples_;  // field samples per block
  long last_checkpoint_step_ = -1;
  std::optional<ProgressMeter> meter_;
  std::optional<RunDirectory> run_directory_;
  bool warned_inflow_ = false;
};

int BowShockRun::execute() {
  dir_ = run_directory_of(options_, scene_);
  const std::vector<std::string> warnings = check_scene_before_run(scene_, options_.force);
  const DirectoryMode mode = options_.resume      ? DirectoryMode::resume
                             : options_.overwrite ? DirectoryMode::overwrite
                                                  : DirectoryMode::create;
  RunDirectory::check(dir_, mode);
  for (const std::string& w : warnings) std::cerr << "granshock: warning: " << w << "\n";

  total_steps_ = scene_.total_steps();
  series_ = every_seconds(scene_.run.series_interval_s, scene_.run.duration_s, scene_.setup.dt);
  snapshots_ =
      every_seconds(scene_.run.snapshot_interval_s, scene_.run.duration_s, scene_.setup.dt);
  checkpoints_ =
      every_seconds(scene_.run.checkpoint_interval_s, scene_.run.duration_s, scene_.setup.dt);
  solver_ = make_solver(scene_.setup, scene_.capacity_estimate());
  configure_sampling();

  // Every check is done: from here on the run owns the directory (and holds its lock).
  run_directory_.emplace(RunDirectory::claim(dir_, mode));
  if (options_.resume) {
    resume();
  } else {
    start_fresh();
  }
  first_step_ = solver_->steps_done();
  meter_.emplace(first_step_, total_steps_, scene_.run.progress_interval_s);

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    return advance_to_end();
  } catch (const UserError& e) {
    // In the loop these are failed writes (a full disk): say what survives.
    throw UserError(fmt::format(
        "{}; {}", e.what(),
        last_checkpoint_step_ >= 0
            ? fmt::format("checkpoint.h5 (step {}) is intact: make room and continue with "
                          "--resume",
                          last_checkpoint_step_)
            : std::string("no checkpoint had been written yet")));
  }
}

// The time loop from the current step to the end, a signal or --stop-after-steps.
int BowShockRun::advance_to_end() {
  long step = first_step_;
  while (step < total_steps_) {
    // Advance to the next event (insertion, output) or a slice of about 0.25 s of wall
    // time, so that progress and signals are answered promptly.
    long next = std::min(total_steps_, step + meter_->steps_per(0.25, 50));
    next = std::min(next, (step / inflow_.period_steps() + 1) * inflow_.period_steps());
    for (const Schedule* s : {&series_, &snapshots_, &checkpoints_})
      next = std::min(next, s->next_after(step));
    next = std::min(next, next_sample_after(step));
    if (options_.stop_after_steps > 0)
      next = std::min(next, first_step_ + options_.stop_after_steps);
    particle_steps_ += double(solver_->size()) * double(next - step);
    solver_->advance(next - step);
    step = next;
    actions_at(step);
    warn_if_inflow_falls_short();
    if (meter_->due() && !options_.quiet)
      meter_->report(step, step * scene_.setup.dt, long(solver_->size()),
                     solver_->diagnostics().contacts, particle_steps_, inflow_note());
    if (g_signal != 0) {
      write_checkpoint_now();
      finish(false);
      std::cerr << fmt::format(
          "granshock: interrupted at step {}; checkpoint written, continue with --resume\n", step);
      return 128 + int(g_signal);
    }
    if (options_.stop_after_steps > 0 && step >= first_step_ + options_.stop_after_steps &&
        step < total_steps_) {
      write_checkpoint_now();
      finish(false);
      std::cerr << fmt::format(
          "granshock: stopped after {} steps at step {}; continue with --resume\n",
          options_.stop_after_steps, step);
      return 0;
    }
  }
  finish(true);
  return 0;
}

void BowShockRun::start_fresh() {
  run_file_.emplace(
      RunFile::create(dir_ / "run.h5", loaded_.as_given, loaded_.resolved, scene_.setup.dim));
  solver_->set_particles(HostParticles{});
  inflow_.prefill(*solver_);
  actions_at(0);
}

// Everything is checked before anything changes: a refused checkpoint leaves the run
// directory as it was.
void BowShockRun::resume() {
  const fs::path path = dir_ / "checkpoint.h5";
  CheckpointExtras extras;
  const SolverState state = read_checkpoint(path, extras);
  if (extras.scene_resolved != loaded_.resolved) {
    const std::vector<std::string> keys = differing_keys(extras.scene_resolved, loaded_.resolved);
    throw UserError(fmt::format(
        "--resume: scene key{} {} differ{} from the run in '{}'; resume with the same scene "
        "file and --set options (docs/scene_format.md: no key may change on resume)",
        keys.size() == 1 ? "" : "s", fmt::join(keys, ", "), keys.size() == 1 ? "s" : "",
        dir_.string()));
  }
  try {
    solver_->import_state(state);
    check_run(state, extras, run_fit(state.step));
  } catch (const InvalidCheckpoint& e) {
    throw refuse_checkpoint(path, e);
  }
  inflow_.restore(extras.rng_counter, extras.inserted, extras.insertion_carry);
  const auto grid_end = extras.bin_sums.begin() + extras.bin_shape[0];
  const auto profile_end = grid_end + extras.bin_shape[1];
  solver_->restore_field_sums({extras.bin_sums.begin(), grid_end}, {grid_end, profile_end});
  for (std::size_t b = 0; b < samples_.size(); ++b) samples_[b] = long(*(profile_end + long(b)));
  wall_before_ = extras.wall_seconds_so_far;
  last_checkpoint_step_ = state.step;
  run_file_.emplace(RunFile::open_for_resume(dir_ / "run.h5", state.step));
}

// Everything that happens at a step boundary, in a fixed order (a checkpoint at step s
// is taken after the insertion and outputs of step s, and a resumed run starts after them).
void BowShockRun::actions_at(long step) {
  inflow_.insert_if_due(*solver_, step);
  if (sample_due(step)) {
    const int block = block_of(step);
    solver_->sample_fields(block);
    ++samples_[block];
  }
  if (series_.due(step) || step == total_steps_) write_series_row(step);
  if (snapshots_.due(step) || step == total_steps_) write_snapshot(step);
  if (checkpoints_.due(step) || step == total_steps_) write_checkpoint_now();
}

void BowShockRun::write_series_row(long step) {
  const Diagnostics d = solver_->diagnostics();
  const RemovalCounts removed = solver_->removed();
  TimeSeriesRow row;
  row.step = step;
  row.time = step * scene_.setup.dt;
  row.particles = long(solver_->size());
  row.kinetic_energy = d.kinetic_energy + d.rotational_energy;
  row.temperature = mixture_temperature(scene_, solver_->species_moments());
  row.contacts = d.contacts;
  check_health(step, d);
  row.inserted = inflow_.inserted();
  row.deleted_outlet = removed.high[1];
  row.deleted_inlet = removed.low[1];
  run_file_->append_time_series(row);
}

void BowShockRun::write_snapshot(long step) {
  run_file_->append_snapshot(step, step * scene_.setup.dt, solver_->particles());
  write_particles_xdmf(dir_ / "run.xmf", "run.h5", run_file_->frames(), run_file_->dim(),
                       run_file_->particle_capacity());
}

void BowShockRun::write_checkpoint_now() {
  const long step = solver_->steps_done();
  if (step == last_checkpoint_step_) return;
  CheckpointExtras extras;
  extras.rng_counter = inflow_.events();
  extras.inserted = inflow_.inserted();
  const RemovalCounts removed = solver_->removed();
  extras.deleted_outlet = removed.high[1];
  extras.deleted_inlet = removed.low[1];
  extras.insertion_carry = inflow_.carry();
  extras.wall_seconds_so_far = wall_before_ + (meter_ ? meter_->elapsed_s() : 0.0);
  extras.scene_resolved = loaded_.resolved;
  extras.bin_sums = solver_->field_sums(false);
  const std::vector<double> profile = solver_->field_sums(true);
  extras.bin_shape = {long(extras.bin_sums.size()), long(profile.size()), long(samples_.size())};
  extras.bin_sums.insert(extras.bin_sums.end(), profile.begin(), profile.end());
  extras.bin_sums.insert(extras.bin_sums.end(), samples_.begin(), samples_.end());
  run_file_->flush();
  write_checkpoint(dir_ / "checkpoint.h5", solver_->export_state(), extras);
  last_checkpoint_step_ = step;
}

// The price of the run's time step on the contact law: e_eff of every pair, measured
// with the same kernels at the run's dt, at the mean inflow speed and at the fastest
// impact speed the time-step guard assumes.
nlohmann::json BowShockRun::restitution_at_dt() const {
  nlohmann::json out = nlohmann::json::object();
  const int n = int(scene_.setup.species.size());
  for (int a = 0; a < n; ++a) {
    for (int b = scene_.setup.obstacle ? -1 : a; b < n; ++b) {
      if (b >= 0 && b < a) continue;
      nlohmann::json entry;
      for (const auto& [label, speed] :
           {std::pair<const char*, double>{"at_inflow_speed", scene_.inflow.speed_m_per_s},
            {"at_fastest_impact", scene_.fastest_impact_speed()}}) {
        const CollisionResult r = collide_species(scene_.setup, a, b, speed, scene_.setup.dt, true);
        entry[label] = {{"speed", speed}, {"e_eff", r.e_eff}, {"dt_over_tc", r.dt / r.t_c}};
        entry["e_in"] = r.e_in;
        out[r.pair] = entry;
      }
    }
  }
  return out;
}

void BowShockRun::finish(bool completed) {
  write_field_sums();
  run_file_->flush();
  const double wall = wall_before_ + meter_->elapsed_s();
  const long steps = solver_->steps_done();
  const RemovalCounts removed = solver_->removed();
  const TimeStepAssessment guard = assess_time_step(scene_);
  nlohmann::json j;
  j["scene"] = scene_.name;
  j["completed"] = completed;
  j["steps"] = steps;
  j["simulated_time"] = steps * scene_.setup.dt;
  j["wall_seconds"] = wall;
  // Rate of this leg only (earlier legs of a resumed run are in wall_seconds).
  const double leg_wall = meter_->elapsed_s();
  j["particles_final"] = solver_->size();
  j["inserted"] = inflow_.inserted();
  j["inflow"] = inflow_summary();
  j["deleted"] = removed.total();
  j["deleted_outlet"] = removed.high[1];
  j["deleted_inlet"] = removed.low[1];
  j["dt"] = scene_.setup.dt;
  j["t_c"] = guard.t_c;
  j["dt_over_tc"] = guard.dt_over_tc();
  j["impact_speed_for_t_c"] = guard.impact_speed;
  j["stiffest_pair"] = guard.stiffest_pair;
  j["inflow_sigma"] = scene_.inflow.sigma;
  j["ma_inf_target"] =
      scene_.inflow.target_mach ? nlohmann::json(*scene_.inflow.target_mach) : nlohmann::json();
  j["variant"] = solver_->variant();
  j["backend"] = Kokkos::DefaultExecutionSpace::name();
  j["threads"] = Kokkos::DefaultExecutionSpace().concurrency();
  j["list_builds"] = solver_->list_builds();
  j["particle_steps_per_second"] = leg_wall > 0 ? particle_steps_ / leg_wall : 0.0;
  j["effective_restitution_at_dt"] = restitution_at_dt();
  write_file_atomically(dir_ / "summary.json", j.dump(2) + "\n");
  if (completed && run_file_) {
    // The field analysis reads run.h5, which must be closed first.
    run_file_.reset();
    if (run_has_field_sums(dir_))
      fields_command({dir_}, {}, FieldsCommandOptions{true, options_.quiet});
  }
  if (completed && !options_.quiet)
    std::cout << fmt::format(
        "granshock: {} done: {} steps, {:.4g} s simulated in {:.1f} s wall, {:.3g} "
        "particle-steps/s, "
        "{} particles at the end; results in {}\n",
        scene_.name, steps, steps * scene_.setup.dt, wall,
        j["particle_steps_per_second"].get<double>(), solver_->size(), dir_.string());
}

// Square bins over the whole domain and, with an obstacle, a strip 4 d wide on its axis
// cut into 0.5 d bins from the inlet to the cylinder surface (the stagnation-line
// profile that resolves the detachment length better than 3 d bins).
void BowShockRun::configure_sampling() {
  BinLayout& g = sampling_.grid;
  g.n_species = int(scene_.setup.species.size());
  g.bin_size = scene_.bin_size_m;
  g.nx = std::max(1, int(scene_.setup.box.length(0) / g.bin_size + 1e-9));
  g.ny = std::max(1, int(scene_.setup.box.length(1) / g.bin_size + 1e-9));
  g.x0 = scene_.setup.box.lo[0];
  g.y0 = scene_.setup.box.lo[1];
  g.blocks = scene_.run.blocks;
  sampling_.strategy = scene_.field_scatter;
  if (scene_.setup.obstacle) {
    const auto& c = *scene_.setup.obstacle;
    ProfileLayout& p = sampling_.profile;
    p.x_lo = c.centre[0] - 2 * scene_.d_m;
    p.x_hi = c.centre[0] + 2 * scene_.d_m;
    p.y0 = scene_.setup.box.lo[1];
    p.dy = 0.5 * scene_.d_m;
    p.n = std::max(1, int((c.centre[1] - 0.5 * c.diameter_m - p.y0) / p.dy));
  }
  solver_->configure_sampling(sampling_);
  samples_.assign(g.blocks, 0);
  production_first_step_ = long(std::llround(scene_.run.production_start_s / scene_.setup.dt));
}

bool BowShockRun::sample_due(long step) const {
  return step >= production_first_step_ && step < total_steps_ &&
         (step - production_first_step_) % scene_.run.sample_every == 0;
}

// The block of the production window a sample at `step` adds to.
int BowShockRun::block_of(long step) const {
  const long span = total_steps_ - production_first_step_;
  return int(std::min<long>(sampling_.grid.blocks - 1,
                            (step - production_first_step_) * sampling_.grid.blocks / span));
}

// What the schedule and the scene say about a checkpoint taken at `step`.
RunFit BowShockRun::run_fit(long step) const {
  RunFit f;
  f.total_steps = total_steps_;
  f.insertion_events = inflow_.events_by(step);
  f.max_carry = inflow_.particles_per_batch() * double(step / inflow_.period_steps() + 1);
  f.dt = scene_.setup.dt;
  for (const Species& species : scene_.setup.species) {
    f.mass.push_back(species.mass_kg());
    f.inertia.push_back(species.moment_of_inertia());
  }
  f.max_diameter = scene_.setup.max_diameter();
  f.inflow_energy = inflow_energy();
  const BinLayout& g = sampling_.grid;
  f.quantities = g.quantities();
  f.n_species = g.n_species;
  f.grid_sums = long(g.bins()) * g.quantities() * g.blocks;
  f.profile_sums = long(sampling_.profile.n) * g.quantities() * g.blocks;
  f.samples.assign(std::size_t(g.blocks), 0);
  for (long s = production_first_step_; s <= step && s < total_steps_; s += scene_.run.sample_every)
    ++f.samples[std::size_t(block_of(s))];
  return f;
}

long BowShockRun::next_sample_after(long step) const {
  if (step < production_first_step_) return production_first_step_;
  const long every = scene_.run.sample_every;
  return production_first_step_ + ((step - production_first_step_) / every + 1) * every;
}

// Kinetic energy of a mean-mass particle at the inflow's mean velocity and fluctuation.
double BowShockRun::inflow_energy() const {
  return 0.5 * scene_.mean_mass() *
         (scene_.inflow.speed_m_per_s * scene_.inflow.speed_m_per_s +
          2 * scene_.inflow.sigma * scene_.inflow.sigma);
}

// DESIGN.md section 4: a run either stays correct or stops with a diagnosis. A NaN or
// infinite state, or a mean kinetic energy per particle 100 times that of the inflow
// (energy is only ever supplied by the inflow), means the integration has blown up,
// almost always because dt is too large for the impacts that occur.
// core/checkpoint_run_checks.cpp refuses to resume a state past the same limit.
void BowShockRun::check_health(long step, const Diagnostics& d) const {
  const double per_particle_inflow = inflow_energy();
  const double per_particle =
      solver_->size() > 0 ? d.kinetic_energy / double(solver_->size()) : 0.0;
  if (d.non_finite == 0 && per_particle <= 100 * per_particle_inflow) return;
  const TimeStepAssessment guard = assess_time_step(scene_);
  throw NumericalFailure(
      fmt::format("the integration blew up at step {} (t = {:.4g} s): {} particles with a "
                  "non-finite state, mean "
                  "kinetic energy {:.3g} times the inflow's; dt = {:.3g} s is {:.2f} t_c (stable "
                  "limit {:.3g} s); "
                  "reduce time.dt",
                  step, step * scene_.setup.dt, d.non_finite, per_particle / per_particle_inflow,
                  scene_.setup.dt, guard.dt_over_tc(), guard.dt_stable));
}

// docs/scene_format.md, "The inflow": a strip that cannot take what the inflow asks for
// (area fraction near the insertion limit, a shock reaching the inlet) is reported, once,
// as soon as the shortfall passes InflowController::kShortfallWarning.
void BowShockRun::warn_if_inflow_falls_short() {
  if (warned_inflow_ || !inflow_.falls_short()) return;
  warned_inflow_ = true;
  std::cerr << fmt::format(
      "granshock: warning: the inflow falls short: {:.0f} of {:.0f} requested particles "
      "({:.1f}%) found no room in the insertion strip by t = {:.4g} s; phi_inf will be below "
      "its target {:g} (summary.json: inflow)\n",
      inflow_.shortfall(), inflow_.requested(), 100 * inflow_.shortfall() / inflow_.requested(),
      solver_->time(), scene_.inflow.area_fraction);
}

std::string BowShockRun::inflow_note() const {
  if (inflow_.shortfall() < 1.0) return {};
  return fmt::format("inflow short by {:.0f} ({:.1f}%, backlog {:.0f})", inflow_.shortfall(),
                     100 * inflow_.shortfall() / inflow_.requested(), inflow_.backlog());
}

nlohmann::json BowShockRun::inflow_summary() const {
  const double requested = inflow_.requested();
  nlohmann::json j{
      {"requested", requested},
      {"inserted", inflow_.inserted()},
      {"backlog", inflow_.backlog()},
      {"lost", inflow_.shortfall() - inflow_.backlog()},
      {"achieved_fraction", requested > 0 ? double(inflow_.inserted()) / requested : 1.0},
      {"falls_short", inflow_.falls_short()}};
  return j;
}

// The accumulated sums in run.h5 (layout: core/bin_layout.hpp, docs/output_format.md).
void BowShockRun::write_field_sums() {
  const BinLayout& g = sampling_.grid;
  RunFile& f = *run_file_;
  f.write_array("/fields/grid/sums", solver_->field_sums(false),
                {g.blocks, g.ny, g.nx, g.quantities()});
  f.write_array("/fields/grid/samples", std::vector<double>(samples_.begin(), samples_.end()),
                {g.blocks});
  f.write_attribute("/fields/grid", "nx", long(g.nx));
  f.write_attribute("/fields/grid", "ny", long(g.ny));
  f.write_attribute("/fields/grid", "blocks", long(g.blocks));
  f.write_attribute("/fields/grid", "n_species", long(g.n_species));
  f.write_attribute("/fields/grid", "x0", g.x0);
  f.write_attribute("/fields/grid", "y0", g.y0);
  f.write_attribute("/fields/grid", "bin_size", g.bin_size);
  f.write_attribute("/fields/grid", "production_start", scene_.run.production_start_s);
  f.write_attribute("/fields/grid", "production_end", scene_.run.duration_s);
  f.write_attribute("/fields/grid", "sample_every", scene_.run.sample_every);
  const ProfileLayout& p = sampling_.profile;
  if (p.n > 0) {
    f.write_array("/fields/profile/sums", solver_->field_sums(true),
                  {g.blocks, p.n, g.quantities()});
    f.write_array("/fields/profile/samples", std::vector<double>(samples_.begin(), samples_.end()),
                  {g.blocks});
    f.write_attribute("/fields/profile", "n", long(p.n));
    f.write_attribute("/fields/profile", "x_lo", p.x_lo);
    f.write_attribute("/fields/profile", "x_hi", p.x_hi);
    f.write_attribute("/fields/profile", "y0", p.y0);
    f.write_attribute("/fields/profile", "dy", p.dy);
  }
}

}  // namespace

RunCheck check_run(const RunOptions& o) {
  const LoadedScene loaded = load_scene_file(o.scene_file, o.overrides);
  RunCheck c;
  c.warnings = check_scene_before_run(loaded.scene, o.force);
  c.directory = run_directory_of(o, loaded.scene);
  RunDirectory::check(c.directory, o.resume      ? DirectoryMode::resume
                                   : o.overwrite ? DirectoryMode::overwrite
                                                 : DirectoryMode::create);
  c.resolved_scene = loaded.resolved;
  return c;
}

int run_scene(const RunOptions& o) {
  if (o.dry_run) {
    const RunCheck c = check_run(o);
    for (const std::string& w : c.warnings) std::cerr << "granshock: warning: " << w << "\n";
    std::cout << c.resolved_scene;
    return 0;
  }
  BowShockRun run(o, load_scene_file(o.scene_file, o.overrides));
  return run.execute();
}

}  // namespace granshock

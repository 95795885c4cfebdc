#include "cases/bow_shock/backend_mover.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "cases/bow_shock/machine_load.hpp"
#include "core/choice_names.hpp"

namespace granshock {

void BackendMover::choose_start(int processes) {
  const int threads = switchable_host_threads();
  if (mode_ == BackendSwitchMode::off || processes != 1 || threads <= 1) return;
  switch_.emplace();
  if (mode_ != BackendSwitchMode::automatic) return;
  // The threads are tried again only once the others leave them room (or /proc cannot
  // tell): a try beside the same load would only cost.
  switch_->set_threads_free([threads] { return !load_leaving_no_room(threads); });
  const std::optional<MachineLoad> load = load_leaving_no_room(threads);
  if (!load) return;
  switch_->start_on_one_thread();
  backend_ = Backend::serial;
  note(fmt::format(
      "granshock: note: starting on one thread: {} other task{} running on the {} CPU{} this "
      "process may use, beside which {} threads would wait for each other; trying the threads "
      "again later (--backend-switch off keeps the threads)",
      load->others_running, load->others_running == 1 ? " is" : "s are", load->cpus,
      load->cpus == 1 ? "" : "s", threads));
}

void BackendMover::advance(Solver& solver, long steps, double particle_steps) {
  const auto start = std::chrono::steady_clock::now();
  solver.advance(steps);
  if (!switch_) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long switches = switch_->switches();
  switch_->observe(particle_steps, seconds);
  // One note when the run settles on the other backend (a try alone says nothing); with
  // --quiet, in the log alone.
  if (switch_->switches() == switches || mode_ != BackendSwitchMode::automatic) return;
  const bool one_thread = switch_->current() == Backend::serial;
  note(fmt::format(
      "granshock: note: {} ({:.3g} particle-steps/s on {} threads, {:.3g} on one); trying "
      "the other again later (--backend-switch off keeps the threads)",
      one_thread ? "continuing on one thread: the threads run slower than one would (another "
                   "process is busy on this machine)"
                 : "back to the threads: they run faster again",
      switch_->threads_rate(), switchable_host_threads(), switch_->one_thread_rate()));
}

// The backend the next slice runs on: the switch's choice, or with --backend-switch
// alternate (a check that both give the same run, not a speed-up) the other one each time.
Backend BackendMover::next_backend() const {
  if (mode_ != BackendSwitchMode::alternate) return switch_->current();
  return backend_ == Backend::serial ? Backend::default_space : Backend::serial;
}

// The solver's whole state moves to a solver on the other backend, as a resume would move
// it from a checkpoint: the trajectory goes on bitwise the same (docs/benchmarks.md, "A
// busy machine"). The old solver is released first, so that the two never hold memory at
// once.
void BackendMover::move_if_due(std::unique_ptr<Solver>& solver, std::size_t capacity,
                               const MakeSolver& make) {
  if (!switch_) return;
  const Backend next = next_backend();
  if (next == backend_) return;
  const SolverState state = solver->export_state();
  const std::vector<double> grid = solver->field_sums(false);
  const std::vector<double> profile = solver->field_sums(true);
  solver.reset();
  solver = make(next, std::max(capacity, state.size()));
  solver->import_state(state);
  solver->restore_field_sums(grid, profile);
  backend_ = next;
  ++moves_;
}

nlohmann::json BackendMover::summary() const {
  if (!switch_) return nullptr;
  return {{"mode", choice_name(mode_)},
          {"started_on", switch_->started_on_one_thread() ? "one thread" : "threads"},
          {"ended_on", backend_ == Backend::serial ? "one thread" : "threads"},
          {"moves", moves_},
          {"tries", switch_->tries()},
          {"tries_skipped_busy", switch_->skipped_tries()},
          {"seconds_on_one_thread", switch_->seconds_on_one_thread()},
          {"seconds_timed", switch_->seconds_total()},
          {"last_threads_rate", switch_->threads_rate()},
          {"last_one_thread_rate", switch_->one_thread_rate()}};
}

void BackendMover::note(const std::string& line) {
  if (quiet_)
    log_.record(line);
  else
    log_.say(line);
}

}  // namespace granshock

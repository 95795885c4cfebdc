// The backend a one-process bow-shock run steps on, threads or one thread, and the move of
// its solver between the two (backend_switch.hpp decides; docs/benchmarks.md, "A busy
// machine"): the backend to start on, each slice of the time loop timed for the switch,
// the move when the switch (or --backend-switch alternate) asks for the other backend,
// and summary.json's "backend_switch".
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "cases/bow_shock/backend_switch.hpp"
#include "cases/bow_shock/run_log.hpp"
#include "core/run_modes.hpp"
#include "core/solver.hpp"

namespace granshock {

class BackendMover {
 public:
  // A new solver on a backend with room for `capacity` particles, set up as the run's
  // (sampling, decomposition) but without particles.
  using MakeSolver = std::function<std::unique_ptr<Solver>(Backend, std::size_t capacity)>;

  BackendMover(BackendSwitchMode mode, bool quiet, RunLog& log)
      : mode_(mode), quiet_(quiet), log_(log) {}

  // Whether the run can move (one process on the host's threads, --backend-switch not
  // off), and the backend to start on: one thread where other processes already keep the
  // CPUs busy (machine_load.hpp), so that neither the calibrations nor the run's first
  // half-second wait at the threads' barriers; the switch tries the threads later.
  void choose_start(int processes);

  Backend backend() const { return backend_; }
  // The wall time a slice of the time loop should last.
  double slice_seconds() const { return switch_ ? switch_->slice_seconds() : 0.25; }
  // steps of `solver`, timed for the switch (particle_steps: over every process).
  void advance(Solver& solver, long steps, double particle_steps);
  // Moves the solver to the backend the next slice runs on, when that is another one.
  void move_if_due(std::unique_ptr<Solver>& solver, std::size_t capacity, const MakeSolver& make);

  // summary.json "backend_switch" (this leg of the run); null where the run cannot move.
  nlohmann::json summary() const;

 private:
  Backend next_backend() const;
  void note(const std::string& line);

  BackendSwitchMode mode_;
  bool quiet_;
  RunLog& log_;
  // From measured rates; none where the run cannot move (several processes, one thread,
  // a GPU, --backend-switch off).
  std::optional<BackendSwitch> switch_;
  Backend backend_ = Backend::default_space;
  long moves_ = 0;
};

}  // namespace granshock

// Threads or one thread, chosen from measured rates while a run goes (docs/benchmarks.md,
// "A busy machine"). On a machine where another process keeps a core busy, the threaded
// step waits at every barrier for a thread the kernel has descheduled: 2 threads beside
// one busy process ran 35 times slower than 1 thread. The run therefore measures its own
// rate in windows of wall time, tries the other backend for one window now and then (at
// doubling gaps, and at once when the rate falls well below what it was), and stays on
// whichever ran faster. Both backends give bitwise the same trajectory (the solver's state
// moves between them as a resume would), so the choice changes only the speed.
#pragma once

#include <functional>

#include "core/solver.hpp"

namespace granshock {

struct BackendSwitchPolicy {
  double window_s = 0.3;        // a rate is measured over at least this much wall time
  double try_window_s = 0.1;    // and a try's over this much: on an idle machine a try of
                                // one thread costs about half of it
  double first_gap_s = 0.5;     // the first try of the other backend, after this long
  double longest_gap_s = 60.0;  // the gaps between tries double up to this
  // After a move the first try of the backend left comes after this long: the load that
  // made the move may lift, but each try of collapsed threads costs a try window and two
  // moves, so they are not tried as early as at the start.
  double gap_after_move_s = 2.0;
  // The settled backend's rate falling below this share of its rate when it was last
  // compared (or the best since) is a sign of new load: the other backend is tried at once.
  double drop = 0.6;
  // The threads must beat one thread by this factor to be taken back: the rates are
  // noisy, and one thread is the safe choice on a busy machine.
  double threads_margin = 1.05;
};

class BackendSwitch {
 public:
  explicit BackendSwitch(BackendSwitchPolicy policy = {});

  // Asked before a try of the threads from one thread: false where the CPUs are still
  // busy (machine_load.hpp), and the try is skipped. Unset: every try is made.
  void set_threads_free(std::function<bool()> threads_free) {
    threads_free_ = std::move(threads_free);
  }
  long skipped_tries() const { return skipped_tries_; }

  // Starts on one thread (another process keeps the cores busy at the start,
  // machine_load.hpp): the threads are tried after gap_after_move_s, as after a move.
  void start_on_one_thread();
  bool started_on_one_thread() const { return started_on_one_thread_; }

  // A slice of the run: `particle_steps` done in `seconds` of wall time on current().
  // Returns the backend the next slice runs on.
  Backend observe(double particle_steps, double seconds);

  Backend current() const { return current_; }
  // The wall time the next slice should last, at the rate of the backend settled on:
  // short while the other one is tried, so that a try of threads that have collapsed (35
  // times slower) lasts about one try window, not a whole slice at a thirty-fifth of the
  // speed.
  double slice_seconds() const { return trying_ ? 0.003 : 0.25; }
  long switches() const { return switches_; }
  long tries() const { return tries_; }
  double seconds_on_one_thread() const { return serial_seconds_; }
  double seconds_total() const { return total_seconds_; }
  // The rates of the last comparison (particle-steps per second; 0 before the first).
  double threads_rate() const { return threads_rate_; }
  double one_thread_rate() const { return serial_rate_; }

 private:
  void start_trying();
  void decide(double tried_rate);

  BackendSwitchPolicy policy_;
  Backend current_ = Backend::default_space;
  Backend settled_ = Backend::default_space;
  bool trying_ = false;
  double settled_rate_ = 0;    // the settled backend's rate before the try
  double reference_rate_ = 0;  // the settled backend's rate to compare new windows with
  double window_steps_ = 0, window_seconds_ = 0;
  bool first_slice_ = true;  // the run's first: start-up costs, not a rate
  double since_try_s_ = 0, gap_s_ = 0;
  bool started_on_one_thread_ = false;
  std::function<bool()> threads_free_;
  long skipped_tries_ = 0;
  long switches_ = 0, tries_ = 0;
  double serial_seconds_ = 0, total_seconds_ = 0;
  double threads_rate_ = 0, serial_rate_ = 0;
};

}  // namespace granshock

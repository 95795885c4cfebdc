#include "cases/bow_shock/backend_switch.hpp"

#include <algorithm>

namespace granshock {

namespace {

Backend other(Backend b) {
  return b == Backend::serial ? Backend::default_space : Backend::serial;
}

}  // namespace

BackendSwitch::BackendSwitch(BackendSwitchPolicy policy)
    : policy_(policy), gap_s_(policy.first_gap_s) {}

void BackendSwitch::start_on_one_thread() {
  current_ = settled_ = Backend::serial;
  started_on_one_thread_ = true;
  gap_s_ = policy_.gap_after_move_s;
}

Backend BackendSwitch::observe(double particle_steps, double seconds) {
  total_seconds_ += seconds;
  if (current_ == Backend::serial) serial_seconds_ += seconds;
  if (first_slice_) {  // the run's first slice holds its start-up (list build, allocations)
    first_slice_ = false;
    return current_;
  }
  window_steps_ += particle_steps;
  window_seconds_ += seconds;
  if (window_seconds_ < (trying_ ? policy_.try_window_s : policy_.window_s)) return current_;
  const double rate = window_steps_ / window_seconds_;
  const double window = window_seconds_;
  window_steps_ = window_seconds_ = 0;
  if (trying_) {
    decide(rate);
    return current_;
  }
  since_try_s_ += window;
  reference_rate_ = std::max(reference_rate_, rate);
  if (since_try_s_ >= gap_s_ || rate < policy_.drop * reference_rate_) {
    // On one thread, a machine still as busy as when the run moved there is not worth a
    // try of the threads (each costs a try window at their collapsed rate and two moves):
    // the try is skipped as a failed one would be, and the gap doubles.
    if (settled_ == Backend::serial && threads_free_ && !threads_free_()) {
      ++skipped_tries_;
      since_try_s_ = 0;
      gap_s_ = std::min(2 * gap_s_, policy_.longest_gap_s);
      return current_;
    }
    settled_rate_ = rate;
    start_trying();
  }
  return current_;
}

void BackendSwitch::start_trying() {
  trying_ = true;
  ++tries_;
  current_ = other(settled_);
  since_try_s_ = 0;
}

void BackendSwitch::decide(double tried_rate) {
  trying_ = false;
  const bool tried_one_thread = current_ == Backend::serial;
  serial_rate_ = tried_one_thread ? tried_rate : settled_rate_;
  threads_rate_ = tried_one_thread ? settled_rate_ : tried_rate;
  const bool better = tried_one_thread ? tried_rate > settled_rate_
                                       : tried_rate > policy_.threads_margin * settled_rate_;
  if (better) {
    settled_ = current_;
    ++switches_;
    reference_rate_ = tried_rate;
    // The load that made the change may lift soon: look again after a short gap.
    gap_s_ = policy_.gap_after_move_s;
  } else {
    current_ = settled_;
    reference_rate_ = settled_rate_;
    gap_s_ = std::min(2 * gap_s_, policy_.longest_gap_s);
  }
}

}  // namespace granshock

// The one-line progress display of long runs: step, simulated time, particles, contacts,
// particle-steps per second and the estimated time to the end, at most every
// `interval` wall seconds.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

namespace granshock {

class ProgressMeter {
 public:
  // Each line, without its newline (a run sends them to its log: run_log.hpp).
  using LineSink = std::function<void(const std::string&)>;
  ProgressMeter(long first_step, long total_steps, double interval_s, std::FILE* out = stderr);
  ProgressMeter(long first_step, long total_steps, double interval_s, LineSink sink);

  bool due() const;
  // particle_steps: done since the meter started (for the rate).
  // note: appended to the line when not empty (e.g. an inflow that falls short).
  void report(long step, double time_s, long particles, long contacts, double particle_steps,
              const std::string& note = {});
  // The prefill's line, in the same form: slabs filled of all, particles placed, ETA.
  void report_prefill(long slabs_done, long slabs, long particles);
  double elapsed_s() const;
  // The run has reached `step`: the step rate is measured from these calls, shown or not
  // (a --quiet run sizes its time slices by it as well).
  void observe(long step);
  // Steps that fit in about `seconds` of wall time at the rate seen so far, `fallback`
  // before the first measurement.
  long steps_per(double seconds, long fallback) const;
  // The shortest wall time a rate is measured over.
  static constexpr double rate_window_s = 0.02;

 private:
  using Clock = std::chrono::steady_clock;
  long first_step_, total_steps_;
  double interval_s_;
  LineSink sink_;
  Clock::time_point start_, last_, rate_since_;
  long rate_since_step_ = 0;
  double step_rate_ = 0;  // steps per wall second
};

}  // namespace granshock

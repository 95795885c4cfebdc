// The progress display of long runs, at most every `interval` wall seconds: rows of the
// thermo table (thermo_table.hpp: step, simulated time, particles, contacts, energy,
// temperature, insertions, deletions, particle-steps per second, the share done and the
// estimated time to the end) under a header shown with the first.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include "cases/bow_shock/thermo_table.hpp"

namespace granshock {

class ProgressMeter {
 public:
  // Each line, without its newline (a run sends them to its log: run_log.hpp).
  using LineSink = std::function<void(const std::string&)>;
  ProgressMeter(long first_step, long total_steps, double interval_s, std::FILE* out = stderr);
  ProgressMeter(long first_step, long total_steps, double interval_s, LineSink sink);

  bool due() const;
  // `row` with its state filled in (step to deleted); particle_steps: done since the meter
  // started (for the rate). Shows the row with its rate, share done and ETA (the header
  // before the first) and returns it so. note: appended to the line when not empty (e.g.
  // an inflow that falls short).
  ThermoRow report(ThermoRow row, double particle_steps, const std::string& note = {});
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
  bool header_shown_ = false;
  double step_rate_ = 0;  // steps per wall second
};

}  // namespace granshock

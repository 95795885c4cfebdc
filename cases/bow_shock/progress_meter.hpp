// The one-line progress display of long runs: step, simulated time, particles, contacts,
// particle-steps per second and the estimated time to the end, at most every
// `interval` wall seconds.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace granshock {

class ProgressMeter {
 public:
  ProgressMeter(long first_step, long total_steps, double interval_s, std::FILE* out = stderr);

  bool due() const;
  // particle_steps: done since the meter started (for the rate).
  // note: appended to the line when not empty (e.g. an inflow that falls short).
  void report(long step, double time_s, long particles, long contacts, double particle_steps,
              const std::string& note = {});
  double elapsed_s() const;
  // Steps that fit in about `seconds` of wall time at the rate seen so far.
  long steps_per(double seconds, long fallback) const;

 private:
  using Clock = std::chrono::steady_clock;
  long first_step_, total_steps_;
  double interval_s_;
  std::FILE* out_;
  Clock::time_point start_, last_;
  long last_step_ = 0;
  double step_rate_ = 0;  // steps per wall second
};

}  // namespace granshock

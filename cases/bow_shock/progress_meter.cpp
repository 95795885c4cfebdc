#include "cases/bow_shock/progress_meter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace granshock {

ProgressMeter::ProgressMeter(long first_step, long total_steps, double interval_s, std::FILE* out)
    : ProgressMeter(first_step, total_steps, interval_s, [out](const std::string& line) {
        std::fprintf(out, "%s\n", line.c_str());
        std::fflush(out);
      }) {}

ProgressMeter::ProgressMeter(long first_step, long total_steps, double interval_s, LineSink sink)
    : first_step_(first_step),
      total_steps_(total_steps),
      interval_s_(interval_s),
      sink_(std::move(sink)),
      start_(Clock::now()),
      last_(start_),
      rate_since_(start_),
      rate_since_step_(first_step) {}

double ProgressMeter::elapsed_s() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

bool ProgressMeter::due() const {
  return std::chrono::duration<double>(Clock::now() - last_).count() >= interval_s_;
}

void ProgressMeter::observe(long step) {
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - rate_since_).count();
  if (since < rate_window_s) return;
  step_rate_ = double(step - rate_since_step_) / since;
  rate_since_ = now;
  rate_since_step_ = step;
}

long ProgressMeter::steps_per(double seconds, long fallback) const {
  return step_rate_ > 0 ? std::max(1L, long(step_rate_ * seconds)) : fallback;
}

void ProgressMeter::report_prefill(long slabs_done, long slabs, long particles) {
  last_ = Clock::now();
  const double elapsed = elapsed_s();
  const double eta = slabs_done > 0 ? elapsed * double(slabs - slabs_done) / slabs_done : 0;
  const int eta_s = int(std::lround(eta));
  sink_(fmt::format("prefill {}/{} slabs ({:.1f}%)  particles {}  ETA {}:{:02d}:{:02d}", slabs_done,
                    slabs, 100.0 * slabs_done / std::max(1L, slabs), particles, eta_s / 3600,
                    eta_s / 60 % 60, eta_s % 60));
}

ThermoRow ProgressMeter::report(ThermoRow row, double particle_steps, const std::string& note) {
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  last_ = now;
  const double overall = elapsed > 0 ? double(row.step - first_step_) / elapsed : 0;
  row.eta_s = overall > 0 ? std::lround(double(total_steps_ - row.step) / overall) : 0;
  row.particle_steps_per_s = elapsed > 0 ? particle_steps / elapsed : 0.0;
  row.done_percent = 100.0 * double(row.step) / double(std::max(1L, total_steps_));
  if (!header_shown_) sink_(thermo_header());
  header_shown_ = true;
  sink_(thermo_line(row) + (note.empty() ? "" : "  " + note));
  return row;
}

}  // namespace granshock

#include "cases/study/study_cost.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "models/obstacle_shapes.hpp"

namespace granshock {

double expected_particles(const Scene& s) {
  double free_area = s.setup.box.length(0) * s.setup.box.length(1);
  if (s.setup.obstacle) free_area -= obstacle_area(*s.setup.obstacle);
  return s.mean_particle_measure() > 0 ? s.inflow_number_per_area() * std::max(0.0, free_area)
                                       : 0.0;
}

double expected_particle_steps(const Scene& s, long steps_done) {
  return expected_particles(s) * double(std::max(0L, s.total_steps() - steps_done));
}

std::string duration_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  const long h = s / 3600, m = s / 60 % 60, sec = s % 60;
  if (h > 99) return fmt::format("{} d {:02d}:{:02d}:{:02d}", h / 24, h % 24, m, sec);
  return fmt::format("{}:{:02d}:{:02d}", h, m, sec);
}

}  // namespace granshock

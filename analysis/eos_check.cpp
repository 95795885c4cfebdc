#include "analysis/eos_check.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace granshock {

namespace {
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}
}  // namespace

EosCheck check_equation_of_state(const BinFields& f, const EosCut& cut) {
  EosCheck c;
  double dilute = 0, dense = 0, dilute_abs = 0, dense_abs = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    if (f.masked[k] || !(f.particle_samples[k] >= cut.min_particle_samples)) continue;
    const double dev = f.eos_deviation[k];
    if (!std::isfinite(dev)) continue;
    if (f.phi[k] < cut.dilute_below) {
      dilute += dev;
      dilute_abs += std::abs(dev);
      ++c.dilute_bins;
    } else if (f.phi[k] >= cut.dense_from) {
      dense += dev;
      dense_abs += std::abs(dev);
      ++c.dense_bins;
    }
  }
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  c.dilute_mean = c.dilute_bins ? dilute / c.dilute_bins : nan;
  c.dilute_mean_abs = c.dilute_bins ? dilute_abs / c.dilute_bins : nan;
  c.dense_mean = c.dense_bins ? dense / c.dense_bins : nan;
  c.dense_mean_abs = c.dense_bins ? dense_abs / c.dense_bins : nan;
  char text[160];
  const char* pattern = "no unmasked bin with %s and at least %.0f particle samples";
  if (!c.dilute_bins) {
    const std::string range = "phi < " + number(cut.dilute_below);
    std::snprintf(text, sizeof text, pattern, range.c_str(), cut.min_particle_samples);
    c.dilute_reason = text;
  }
  if (!c.dense_bins) {
    const std::string range = "phi >= " + number(cut.dense_from);
    std::snprintf(text, sizeof text, pattern, range.c_str(), cut.min_particle_samples);
    c.dense_reason = text;
  }
  return c;
}

}  // namespace granshock

#include "analysis/field_sampling_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/bin_layout.hpp"
#include "core/scene.hpp"
#include "core/user_error.hpp"
#include "models/obstacle_shapes.hpp"
#include "models/sampled_layer.hpp"

namespace granshock {

namespace {

using Limits = FieldSamplingLimits;

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, args...);
  return text;
}

// The stagnation-line profile's bins, as `granshock run` lays them out (0.5 d from the
// inlet to the surface; cases/bow_shock/run_command.cpp, configure_sampling).
double profile_bins(const Scene& s) {
  if (!s.setup.obstacle) return 0;
  const auto& c = *s.setup.obstacle;
  return std::max(1.0, (obstacle_upstream_face(c) - s.setup.box.lo[1]) / (0.5 * s.d_m));
}

// Below a limit by more than round-off: lengths written in d (5 d / 1 d) must not fall
// short of their own limit through binary fractions (0.005 / 0.001 = 4.999...).
bool below(double ratio, double limit) {
  return ratio < limit * (1 - 1e-9);
}

void check_geometry(const Scene& s) {
  const double bin = s.bin_size_m, d = s.d_m;
  const double width = s.setup.box.length(0), length = s.setup.box.length(1);
  const double strip = s.inflow.strip_m;
  if (bin < s.setup.max_diameter() * (1 - 1e-12))
    throw UserError(
        format("numerics.bin_size = %g d is smaller than the particle diameter "
               "%g d; a bin must be at least one particle wide",
               bin / d, s.setup.max_diameter() / d));
  if (below(width / bin, Limits::bins_across_width))
    throw UserError(
        format("numerics.bin_size = %g d leaves %.3g bins across the domain "
               "(domain.width = %g d); the field analysis needs at least %g "
               "(numerics.bin_size <= %.4g d)",
               bin / d, width / bin, width / d, Limits::bins_across_width,
               width / Limits::bins_across_width / d));
  if (s.setup.obstacle) {
    const auto& c = *s.setup.obstacle;
    const double across = obstacle_frontal_width(c);
    const std::string what = with_obstacle_shape(c, [](auto shape) { return shape.width_key; });
    if (below(across / bin, Limits::bins_across_obstacle))
      throw UserError(
          format("numerics.bin_size = %g d leaves %.3g bins across the obstacle "
                 "(%s = %g d); the shock-front rules need at least %g "
                 "(numerics.bin_size <= %.4g d)",
                 bin / d, across / bin, what.c_str(), across / d, Limits::bins_across_obstacle,
                 across / Limits::bins_across_obstacle / d));
    const double gap = obstacle_upstream_face(c) - s.setup.box.lo[1] - strip;
    if (below(gap / bin, Limits::rows_strip_to_obstacle))
      throw UserError(format(
          "numerics.bin_size = %g d leaves %.3g bins between the insertion strip (inflow.strip "
          "= %g d) and the obstacle's upstream surface (%g d further); the upstream state and "
          "the shock-front search need at least %g (numerics.bin_size <= %.4g d)",
          bin / d, gap / bin, strip / d, gap / d, Limits::rows_strip_to_obstacle,
          gap / Limits::rows_strip_to_obstacle / d));
  } else if (below((length - strip) / bin, Limits::rows_strip_to_outlet)) {
    throw UserError(
        format("numerics.bin_size = %g d leaves %.3g bins between the insertion "
               "strip (inflow.strip = %g d) and the outlet (domain.length = %g d); "
               "the upstream state needs at least %g (numerics.bin_size <= %.4g d)",
               bin / d, (length - strip) / bin, strip / d, length / d, Limits::rows_strip_to_outlet,
               (length - strip) / Limits::rows_strip_to_outlet / d));
  }
}

void check_memory(const Scene& s) {
  const double bins = std::floor(s.setup.box.length(0) / s.bin_size_m + 1e-9) *
                          std::floor(s.setup.box.length(1) / s.bin_size_m + 1e-9) +
                      profile_bins(s);
  BinLayout layout;
  layout.n_species = static_cast<int>(s.setup.species.size());
  const double bytes = double(s.run.blocks) * bins * layout.quantities() * 8.0;
  if (bytes > Limits::max_sum_bytes)
    throw UserError(
        format("output.blocks = %d with numerics.bin_size = %g d needs %.3g GiB of "
               "field sums (blocks x %.3g bins x %d quantities x 8 bytes); the limit "
               "is %.3g GiB: use fewer output.blocks or larger bins",
               s.run.blocks, s.bin_size_m / s.d_m, bytes / (1024.0 * 1024 * 1024), bins,
               layout.quantities(), Limits::max_sum_bytes / (1024.0 * 1024 * 1024)));
}

void check_samples(const Scene& s) {
  const long samples = production_samples(s);
  const long needed = long(s.run.blocks) * Limits::samples_per_block;
  const double window = s.run.duration_s - s.run.production_start_s;
  const std::string where = format(
      "the production window [time.production_start, time.duration] = [%g, %g] s holds "
      "%ld field samples at output.sample_every = %ld steps of time.dt = %g s",
      s.run.production_start_s, s.run.duration_s, samples, s.run.sample_every, s.setup.dt);
  if (samples < needed)
    throw UserError(where + format("; output.blocks = %d need at least %ld (%ld per block): "
                                   "output.sample_every <= %ld",
                                   s.run.blocks, needed, Limits::samples_per_block,
                                   std::max(1L, long(window / s.setup.dt / double(needed)))));
  // Particles an upstream grid bin counts per sample at phi_inf.
  const double per_sample = s.inflow_number_per_area() * s.bin_size_m * s.bin_size_m *
                            (s.setup.dim == 3 ? sampled_z_range(s)[1] / s.depth() : 1.0);
  const double expected = per_sample * double(samples);
  if (expected < Limits::upstream_particle_samples)
    throw UserError(
        where + format("; an upstream bin (numerics.bin_size = %g d, inflow.area_fraction = %g) "
                       "would count %.3g particles over them; %g are needed (twice the 20 that "
                       "unmask a bin): output.sample_every <= %ld",
                       s.bin_size_m / s.d_m, s.inflow.area_fraction, expected,
                       Limits::upstream_particle_samples,
                       std::max(1L, long(window / s.setup.dt * per_sample /
                                         Limits::upstream_particle_samples))));
}

}  // namespace

long production_samples(const Scene& s) {
  const long total = s.total_steps();
  const long first = long(std::llround(s.run.production_start_s / s.setup.dt));
  if (total <= first) return 0;
  return (total - first - 1) / s.run.sample_every + 1;
}

void validate_bins(const Scene& s) {
  check_geometry(s);
  check_memory(s);
}

void validate_field_sampling(const Scene& s) {
  validate_bins(s);
  check_samples(s);
}

}  // namespace granshock

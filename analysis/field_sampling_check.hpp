// Refuses, before a run starts, field sampling that cannot give the analysis what it needs
// (docs/fields.md, "Up-front checks"): bins smaller than a particle, too few bins across
// the domain, across the obstacle or between the insertion strip and the obstacle, too few
// samples in the production window, or bin sums too large for memory. Each refusal is one
// UserError line naming the scene key and the limit.
#pragma once

namespace granshock {

struct Scene;

struct FieldSamplingLimits {
  // Bins across the obstacle's diameter: the axis column and one on each side then see the
  // front in front of the cylinder (three points, the fewest that show a bow rather than a
  // line), and the axis column is narrow enough to stand in for the stagnation line.
  static constexpr double bins_across_obstacle = 3;
  // Bins across the domain's width: the same three columns without an obstacle.
  static constexpr double bins_across_width = 3;
  // Bins between the insertion strip and the obstacle's upstream surface: one bin of gap
  // beyond the strip, two rows for the upstream state (phi_up) and two for the front search
  // beyond them (the threshold rule needs a bin on each side of the crossing).
  static constexpr double rows_strip_to_obstacle = 5;
  // Without an obstacle, rows between the strip and the outlet: the gap and the two
  // upstream rows, which start at most one bin past strip + 1 bin.
  static constexpr double rows_strip_to_outlet = 4;
  // Samples per block: a block value averages at least this many samples.
  static constexpr long samples_per_block = 10;
  // Particle samples an upstream grid bin is expected to collect over the window, at
  // phi_inf: twice the masking threshold (20), so that the Poisson scatter of the counts
  // leaves hardly any upstream bin masked (P(N < 20 | mean 40) < 1e-3).
  static constexpr double upstream_particle_samples = 40;
  // Bytes of bin sums (grid and stagnation-line profile, every block): they live on the
  // device beside the particles and are copied to the host and written out at every
  // checkpoint. The paper's largest scenes need 35 MB.
  static constexpr double max_sum_bytes = 1024.0 * 1024.0 * 1024.0;
};

// Throws UserError when the scene's field sampling breaks one of the limits above.
void validate_field_sampling(const Scene& scene);

// The limits on the bins alone (their size against the particles, the domain and the
// obstacle, their sums' bytes), without those on the samples a run's window takes: for a
// map of another code's dump, whose frames are its samples (cases/dump/dump_sums.hpp).
void validate_bins(const Scene& scene);

// The field samples the production window will hold: one at every sample_every-th step
// from round(production_start / dt) up to, not including, round(duration / dt).
long production_samples(const Scene& scene);

}  // namespace granshock

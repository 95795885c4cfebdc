// The field sums of a checkpoint against the scene's bins and sampling schedule, and
// the moments within each bin against each other (layout: core/bin_layout.hpp).
#include <algorithm>

#include "core/checkpoint_check_support.hpp"

namespace granshock::checks {

namespace {

constexpr const char* kSums = "/run/bin_sums";

// Relative slack for inequalities between sums accumulated in different orders.
constexpr double kSlack = 1 + 1e-9;

struct Limits {
  double max_count;        // particles in a bin over a block's samples
  std::vector<double> v2;  // per species: the largest |v|^2 a particle can have
  double virial;           // per particle and sample
};

// Count N, sums Sx, Sy, Sxx, Sxy, Syy of one species in one bin: N is whole, the second
// moments bound the first (Cauchy-Schwarz) and the speed bounds the second.
void check_species(const std::vector<double>& v, std::size_t k, double v2_max, double max_count) {
  const double n = v[k], sx = v[k + 1], sy = v[k + 2], sxx = v[k + 3], sxy = v[k + 4],
               syy = v[k + 5];
  if (n < 0 || n != std::floor(n) || n > max_count)
    fail(fmt::format("{} = {} is not a particle count in [0, {}] (samples x particles inserted)",
                     at(kSums, k), n, max_count));
  if (n == 0) {
    for (std::size_t q = 1; q < 6; ++q)
      if (v[k + q] != 0)
        fail(fmt::format("{} = {} in a bin that saw no particle", at(kSums, k + q), v[k + q]));
    return;
  }
  const double tiny = 1e-300;
  if (sxx < 0 || syy < 0 || sxx + syy > n * v2_max * kSlack)
    fail(
        fmt::format("{}: sums of squared velocities {} and {} are not in [0, {} (count x the "
                    "largest possible speed squared)]",
                    at(kSums, k + 3), sxx, syy, n * v2_max));
  if (sx * sx > n * sxx * kSlack + tiny || sy * sy > n * syy * kSlack + tiny ||
      sxy * sxy > sxx * syy * kSlack + tiny)
    fail(
        fmt::format("{}: velocity sums {}, {}, {} are inconsistent with their squares {}, {} "
                    "(Cauchy-Schwarz)",
                    at(kSums, k + 1), sx, sy, sxy, sxx, syy));
}

// 3-D: sums Sz, Szz of a species with count n (core/bin_layout.hpp: after the virial):
// Szz bounded by the speed, Sz by Szz (Cauchy-Schwarz); none without a particle.
void check_depth_moments(const std::vector<double>& v, std::size_t k, double n, double v2_max) {
  const double sz = v[k], szz = v[k + 1];
  if (n == 0 && (sz != 0 || szz != 0))
    fail(fmt::format("{} = {} in a bin that saw no particle", at(kSums, sz != 0 ? k : k + 1),
                     sz != 0 ? sz : szz));
  if (szz < 0 || szz > n * v2_max * kSlack || sz * sz > n * szz * kSlack + 1e-300)
    fail(
        fmt::format("{}: z velocity sums {} and {} are inconsistent with each other or with {} "
                    "particle samples at the largest possible speed",
                    at(kSums, k), sz, szz, n));
}

// One accumulator (grid or profile): [blocks][bins][quantities] from `first`.
void check_accumulator(const std::vector<double>& v, std::size_t first, std::size_t length,
                       const RunFit& fit, const Limits& limits) {
  const std::size_t blocks = fit.samples.size(), q = std::size_t(fit.quantities);
  if (blocks == 0 || length == 0) return;
  const std::size_t per_block = length / blocks;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t begin = first + b * per_block, end = begin + per_block;
    if (fit.samples[b] == 0) {
      for (std::size_t k = begin; k < end; ++k)
        if (v[k] != 0)
          fail(fmt::format("{} = {} in block {}, which has no samples yet", at(kSums, k), v[k], b));
      continue;
    }
    const double max_count = double(fit.samples[b]) * limits.max_count;
    for (std::size_t bin = begin; bin < end; bin += q) {
      double particles = 0;
      for (int a = 0; a < fit.n_species; ++a) {
        const std::size_t k = bin + std::size_t(6 * a);
        check_species(v, k, limits.v2[std::size_t(a)], max_count);
        particles += v[k];
      }
      const auto check_virial = [&](std::size_t w) {
        if (std::abs(v[w]) > particles * limits.virial)
          fail(
              fmt::format("{} = {}: a virial beyond what {} particle samples with the largest "
                          "possible forces give ({})",
                          at(kSums, w), v[w], particles, particles * limits.virial));
      };
      const std::size_t virial = bin + std::size_t(6 * fit.n_species);
      for (std::size_t w = virial; w < virial + 4; ++w) check_virial(w);
      if (fit.dim == 3) {  // then per species S_z, S_zz, and W_zz last
        for (int a = 0; a < fit.n_species; ++a)
          check_depth_moments(v, virial + 4 + std::size_t(2 * a), v[bin + std::size_t(6 * a)],
                              limits.v2[std::size_t(a)]);
        check_virial(bin + q - 1);
      }
    }
  }
}

}  // namespace

void check_field_sums(const CheckpointExtras& e, const RunFit& fit) {
  const long blocks = long(fit.samples.size());
  const std::vector<long> expected{fit.grid_sums, fit.profile_sums, blocks};
  if (e.bin_shape != expected)
    fail(fmt::format("/run/bin_shape = [{}], but the scene's field sums have [{}, {}, {}]",
                     fmt::join(e.bin_shape, ", "), fit.grid_sums, fit.profile_sums, blocks));
  const std::size_t tail = std::size_t(fit.grid_sums + fit.profile_sums);
  for (std::size_t b = 0; b < fit.samples.size(); ++b)
    if (e.bin_sums[tail + b] != double(fit.samples[b]))
      fail(fmt::format("{} = {} samples in block {}, but the schedule gives {} by this step",
                       at(kSums, tail + b), e.bin_sums[tail + b], b, fit.samples[b]));
  const long q = fit.quantities;
  const long expected_q = fit.dim == 3 ? 8L * fit.n_species + 5 : 6L * fit.n_species + 4;
  if (q != expected_q || fit.grid_sums % (blocks * q) != 0 || fit.profile_sums % (blocks * q) != 0)
    throw std::logic_error("check_field_sums: RunFit does not describe core/bin_layout.hpp");

  // The budget of the run's health check (check_energy) for the most particles the run
  // ever held, and the force that would blow a particle up within half a step.
  const double budget = 100 * double(std::max(e.inserted, 1L)) * fit.inflow_energy;
  Limits limits;
  limits.max_count = double(std::max(e.inserted, 1L));
  for (double m : fit.mass) limits.v2.push_back(2 * budget / m);
  const double m_max = largest(fit.mass);
  const double force = 4 * std::sqrt(2 * budget * m_max) / fit.dt;
  // W = sum over contacts of r_ij (x) F_ij / 2, |r_ij| <= d_max, and fewer than 16
  // contacts (the 3-D history slots, kernels/particles/particle_store.hpp).
  limits.virial = 0.5 * fit.max_diameter * 16 * force;
  check_accumulator(e.bin_sums, 0, std::size_t(fit.grid_sums), fit, limits);
  check_accumulator(e.bin_sums, std::size_t(fit.grid_sums), std::size_t(fit.profile_sums), fit,
                    limits);
}

}  // namespace granshock::checks

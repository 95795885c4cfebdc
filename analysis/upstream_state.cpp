#include "analysis/upstream_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/kinetic_theory.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

UpstreamState undetermined(UpstreamState s, std::string reason) {
  s.phi = s.temperature = s.uy = s.sound_speed = s.mach = s.mach_mixture_mean = s.mach_paper_sum =
      kNaN;
  s.reason = std::move(reason);
  return s;
}

std::string in_d(double length, const FieldPhysics& phys) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g d", length / phys.d);
  return text;
}

}  // namespace

UpstreamState measure_upstream(const BinFields& f, const BinSums& grid, const FieldPhysics& phys,
                               int row_begin, int row_end) {
  UpstreamState s;
  s.row_begin = std::max(row_begin, 0);
  s.row_end = std::max(row_end, s.row_begin);
  const std::string rows =
      "rows " + std::to_string(s.row_begin) + "-" + std::to_string(s.row_end - 1);
  const double top = grid.y0 + s.row_end * grid.dy;  // upper edge of the last row
  if (s.row_end > f.ny || s.row_end == s.row_begin)
    return undetermined(s, rows + " are not all in the grid, which has " + std::to_string(f.ny) +
                               (f.ny == 1 ? " row of " : " rows of ") + in_d(grid.dy, phys));
  // A bin larger than the domain holds empty space beyond it, which dilutes phi.
  if (top > phys.box_y_hi + 1e-9 * grid.dy)
    return undetermined(s, rows + " reach y = " + in_d(top, phys) + ", beyond the domain's end (" +
                               in_d(phys.box_y_hi, phys) + ")");
  if (phys.obstacle && top > phys.obstacle->face + 1e-9 * grid.dy)
    return undetermined(s, rows + " reach y = " + in_d(top, phys) +
                               ", past the obstacle's upstream surface (" +
                               in_d(phys.obstacle->face, phys) + "): they are not upstream");
  double phi_sum = 0, weight = 0, t_sum = 0, uy_sum = 0;
  int phi_bins = 0;
  std::vector<double> species(static_cast<std::size_t>(f.n_species), 0.0);
  for (int iy = s.row_begin; iy < s.row_end; ++iy) {
    for (int ix = 0; ix < f.nx; ++ix) {
      const std::size_t k = f.index(iy, ix);
      if (std::isfinite(f.phi[k])) {
        phi_sum += f.phi[k];
        ++phi_bins;
      }
      if (f.masked[k]) continue;
      const double w = f.particle_samples[k];
      weight += w;
      t_sum += w * f.temperature[k];
      uy_sum += w * f.uy[k];
      for (std::size_t a = 0; a < species.size(); ++a) species[a] += f.species_samples[a][k];
      ++s.bins;
    }
  }
  const int all_bins = (s.row_end - s.row_begin) * f.nx;
  // Phi is averaged over every sampled bin and T over the unmasked ones weighted by their
  // counts; with most bins masked the rows hold too few particles for a temperature.
  if (2 * s.bins < all_bins || phi_bins == 0)
    return undetermined(s, "only " + std::to_string(s.bins) + " of the " +
                               std::to_string(all_bins) + " bins of " + rows +
                               " are unmasked (at least half must be; a masked bin has too few "
                               "particle samples)");
  s.phi = phi_sum / phi_bins;
  s.temperature = t_sum / weight;
  s.uy = uy_sum / weight;
  double total = 0;
  for (double c : species) total += c;
  std::vector<double> xi(species.size());
  for (std::size_t a = 0; a < xi.size(); ++a) xi[a] = species[a] / total;
  auto mach_with = [&](MassDefinition def) {
    return phys.inflow_speed / sound_speed(s.temperature, phys.sound_speed_mass(def, xi), s.phi,
                                           phys.restitution, phys.dim);
  };
  s.mach_mixture_mean = mach_with(MassDefinition::mixture_mean);
  s.mach_paper_sum = mach_with(MassDefinition::paper_sum);
  s.mach =
      phys.mass_definition == MassDefinition::mixture_mean ? s.mach_mixture_mean : s.mach_paper_sum;
  s.sound_speed = phys.inflow_speed / s.mach;
  return s;
}

std::vector<double> upstream_phi_by_block(const BinSums& grid, const FieldPhysics& phys,
                                          int row_begin, int row_end) {
  std::vector<double> out;
  if (row_begin < 0 || row_end > grid.ny || row_end <= row_begin) return out;
  const BinLayout l = grid.layout();
  // phi = sum_a N_a pi d_a^2 / 4 / (S V), over the rows' bins: the same as the mean of the
  // bins' phi (docs/fields.md, section 2).
  double area = 0;
  for (int iy = row_begin; iy < row_end; ++iy) area += grid.bin_area(iy) * grid.nx;
  for (int b = 0; b < grid.blocks; ++b) {
    const double samples = grid.samples[static_cast<std::size_t>(b)];
    if (!(samples > 0)) continue;
    double disks = 0;
    for (int iy = row_begin; iy < row_end; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix)
        for (int a = 0; a < grid.n_species; ++a) {
          const double d = phys.diameter[static_cast<std::size_t>(a)];
          disks += grid.sums[static_cast<std::size_t>(
                       l.offset(b, iy, ix, l.species_index(a, BinLayout::count)))] *
                   M_PI * d * d / 4;
        }
    out.push_back(disks / (samples * area));
  }
  return out;
}

int first_row_beyond_strip(const BinSums& grid, double strip) {
  // Small tolerance: a strip of exactly k bins minus round-off must not skip a row.
  const double rows = (strip + grid.dy - grid.y0) / grid.dy;
  return std::max(0, static_cast<int>(std::ceil(rows - 1e-9)));
}

}  // namespace granshock

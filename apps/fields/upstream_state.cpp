#include "upstream_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinetic_theory.hpp"

namespace granshock {

UpstreamState measure_upstream(const BinFields& f, const FieldPhysics& phys, int row_begin,
                               int row_end) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  UpstreamState s;
  s.row_begin = std::clamp(row_begin, 0, f.ny);
  s.row_end = std::clamp(row_end, s.row_begin, f.ny);
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
  if (s.bins == 0 || phi_bins == 0) {
    s.phi = s.temperature = s.uy = s.sound_speed = s.mach = s.mach_mixture_mean = s.mach_paper_sum =
        nan;
    return s;
  }
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

int first_row_beyond_strip(const BinSums& grid, double strip) {
  // Small tolerance: a strip of exactly k bins minus round-off must not skip a row.
  const double rows = (strip + grid.dy - grid.y0) / grid.dy;
  return std::max(0, static_cast<int>(std::ceil(rows - 1e-9)));
}

}  // namespace granshock

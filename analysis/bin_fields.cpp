#include "analysis/bin_fields.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/kinetic_theory.hpp"

namespace granshock {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void resize_all(BinFields& f) {
  const std::size_t n = f.size();
  for (std::vector<double>* v : {&f.particle_samples,
                                 &f.mean_count,
                                 &f.n,
                                 &f.rho,
                                 &f.phi,
                                 &f.ux,
                                 &f.uy,
                                 &f.speed,
                                 &f.temperature,
                                 &f.temperature_norm,
                                 &f.p_kin_xx,
                                 &f.p_kin_xy,
                                 &f.p_kin_yy,
                                 &f.p_col_xx,
                                 &f.p_col_xy,
                                 &f.p_col_yx,
                                 &f.p_col_yy,
                                 &f.pressure,
                                 &f.pressure_eos,
                                 &f.eos_deviation,
                                 &f.sound_speed,
                                 &f.mach,
                                 &f.sound_speed_mixture_mean,
                                 &f.mach_mixture_mean,
                                 &f.sound_speed_paper_sum,
                                 &f.mach_paper_sum})
    v->assign(n, kNaN);
  f.masked.assign(n, 1);
  for (auto* per_species :
       {&f.species_samples, &f.species_n, &f.species_ux, &f.species_uy, &f.species_temperature})
    per_species->assign(static_cast<std::size_t>(f.n_species), std::vector<double>(n, kNaN));
}

}  // namespace

bool temperature_resolved(double fluctuation, double kinetic, double samples,
                          const MaskRule& rule) {
  // Summing N terms rounds by at most about N eps of their sum (naive summation), and T
  // subtracts sums of that size; the factor covers the three sums of Q and the pooling
  // over blocks.
  const double roundoff =
      rule.roundoff_factor * samples * std::numeric_limits<double>::epsilon() * kinetic;
  return std::isfinite(fluctuation) && fluctuation > roundoff;
}

BinFields compute_bin_fields(const BinSums& sums, const FieldPhysics& phys, const MaskRule& rule) {
  sums.check_consistent();
  BinFields f;
  f.nx = sums.nx;
  f.ny = sums.ny;
  f.n_species = sums.n_species;
  f.dim = sums.dim;
  resize_all(f);
  if (sums.dim != phys.dim)
    throw std::invalid_argument("compute_bin_fields: " + std::to_string(sums.dim) +
                                "-D sums of a " + std::to_string(phys.dim) + "-D scene");
  if (static_cast<std::size_t>(sums.n_species) != phys.mass.size())
    throw std::invalid_argument("compute_bin_fields: sums for " + std::to_string(sums.n_species) +
                                " species, scene has " + std::to_string(phys.mass.size()));
  const double samples = sums.total_samples();
  const double dim = phys.dim;
  const double m_av = phys.m_av();
  const double u_inf = phys.inflow_speed;
  const BinLayout l = sums.layout();
  const std::size_t ns = static_cast<std::size_t>(sums.n_species);

  const bool three_d = sums.dim == 3;
  for (int iy = 0; iy < sums.ny; ++iy) {
    const double area = sums.bin_measure(iy);  // a volume in 3-D
    for (int ix = 0; ix < sums.nx; ++ix) {
      const std::size_t k = f.index(iy, ix);
      if (!(samples > 0)) continue;  // never sampled: everything NaN, masked
      auto q = [&](int a, BinLayout::SpeciesQuantity what) {
        return sums.pooled(iy, ix, l.species_index(a, what));
      };
      auto qz = [&](int a, BinLayout::DepthQuantity what) {
        return three_d ? sums.pooled(iy, ix, l.depth_index(a, what)) : 0.0;
      };

      // Densities (eq. 3) and the mass-averaged velocity.
      double count = 0, mass_count = 0, mass_cx = 0, mass_cy = 0, mass_cz = 0, phi = 0, rho = 0;
      for (std::size_t a = 0; a < ns; ++a) {
        const int ai = static_cast<int>(a);
        const double na_samples = q(ai, BinLayout::count);
        const double n_a = na_samples / (samples * area);
        f.species_samples[a][k] = na_samples;
        f.species_n[a][k] = n_a;
        count += na_samples;
        mass_count += phys.mass[a] * na_samples;
        mass_cx += phys.mass[a] * q(ai, BinLayout::sum_vx);
        mass_cy += phys.mass[a] * q(ai, BinLayout::sum_vy);
        mass_cz += phys.mass[a] * qz(ai, BinLayout::sum_vz);
        const double d_a = phys.diameter[a];
        phi += three_d ? n_a * M_PI * d_a * d_a * d_a / 6 : n_a * M_PI * d_a * d_a / 4;
        rho += phys.mass[a] * n_a;
      }
      f.particle_samples[k] = count;
      f.mean_count[k] = count / samples;
      f.n[k] = count / (samples * area);
      f.phi[k] = phi;
      f.rho[k] = rho;
      if (!(count >= rule.min_particle_samples) || !(count > 0)) continue;

      const double ux = mass_cx / mass_count, uy = mass_cy / mass_count;
      const double uz = mass_cz / mass_count;  // 0 in 2-D
      // Fluctuation tensors about the mixture velocity u (eq. 4): sum (c-u)(c-u).
      double kxx = 0, kxy = 0, kyy = 0, kzz = 0, trace_mass = 0, kinetic_mass = 0;
      std::vector<double> xi(ns);
      for (std::size_t a = 0; a < ns; ++a) {
        const int ai = static_cast<int>(a);
        const double na = q(ai, BinLayout::count), cx = q(ai, BinLayout::sum_vx),
                     cy = q(ai, BinLayout::sum_vy);
        const double qxx = q(ai, BinLayout::sum_vxvx) - 2 * ux * cx + na * ux * ux;
        const double qxy = q(ai, BinLayout::sum_vxvy) - ux * cy - uy * cx + na * ux * uy;
        const double qyy = q(ai, BinLayout::sum_vyvy) - 2 * uy * cy + na * uy * uy;
        kxx += phys.mass[a] * qxx;
        kxy += phys.mass[a] * qxy;
        kyy += phys.mass[a] * qyy;
        // z: sum (c_z - u_z)^2, nothing in 2-D.
        const double cz = qz(ai, BinLayout::sum_vz);
        const double qzz = qz(ai, BinLayout::sum_vzvz) - 2 * uz * cz + na * uz * uz;
        kzz += phys.mass[a] * qzz;
        const double trace_a = qxx + qyy + qzz;  // + 0 in 2-D: the 2-D sum, bit for bit
        trace_mass += phys.mass[a] * trace_a;
        const double kinetic_a =
            q(ai, BinLayout::sum_vxvx) + q(ai, BinLayout::sum_vyvy) + qz(ai, BinLayout::sum_vzvz);
        kinetic_mass += phys.mass[a] * kinetic_a;
        xi[a] = na / count;
        if (na > 0) {
          f.species_ux[a][k] = cx / na;
          f.species_uy[a][k] = cy / na;
        }
        if (na >= rule.min_particle_samples && temperature_resolved(trace_a, kinetic_a, na, rule))
          f.species_temperature[a][k] = phys.mass[a] * trace_a / (dim * na);
      }
      const double temperature = trace_mass / (dim * count);  // sum_a xi_a T_a
      if (!temperature_resolved(trace_mass, kinetic_mass, count, rule)) {
        for (std::size_t a = 0; a < ns; ++a)
          f.species_temperature[a][k] = f.species_ux[a][k] = f.species_uy[a][k] = kNaN;
        continue;
      }
      f.masked[k] = 0;
      f.ux[k] = ux;
      f.uy[k] = uy;
      f.speed[k] = std::hypot(ux, uy);
      f.temperature[k] = temperature;
      f.temperature_norm[k] = temperature / (m_av * u_inf * u_inf);

      const double norm = 1.0 / (samples * area);
      f.p_kin_xx[k] = kxx * norm;
      f.p_kin_xy[k] = kxy * norm;
      f.p_kin_yy[k] = kyy * norm;
      f.p_col_xx[k] = sums.pooled(iy, ix, l.virial_index(BinLayout::w_xx)) * norm;
      f.p_col_xy[k] = sums.pooled(iy, ix, l.virial_index(BinLayout::w_xy)) * norm;
      f.p_col_yx[k] = sums.pooled(iy, ix, l.virial_index(BinLayout::w_yx)) * norm;
      f.p_col_yy[k] = sums.pooled(iy, ix, l.virial_index(BinLayout::w_yy)) * norm;
      const double zz = three_d ? kzz * norm + sums.pooled(iy, ix, l.w_zz_index()) * norm : 0.0;
      f.pressure[k] = (f.p_kin_xx[k] + f.p_kin_yy[k] + f.p_col_xx[k] + f.p_col_yy[k] + zz) / dim;
      f.pressure_eos[k] = f.n[k] * temperature * pressure_factor(phi, phys.restitution, phys.dim);
      f.eos_deviation[k] = f.pressure[k] / f.pressure_eos[k] - 1;

      // Sound speed (eq. 6) with both masses of eq. 7.
      const double factor = sound_speed_factor(phi, phys.restitution, phys.dim);
      const double m_mean = phys.sound_speed_mass(MassDefinition::mixture_mean, xi);
      const double m_sum = phys.sound_speed_mass(MassDefinition::paper_sum, xi);
      f.sound_speed_mixture_mean[k] = std::sqrt(temperature / m_mean * factor);
      f.sound_speed_paper_sum[k] = std::sqrt(temperature / m_sum * factor);
      f.mach_mixture_mean[k] = f.speed[k] / f.sound_speed_mixture_mean[k];
      f.mach_paper_sum[k] = f.speed[k] / f.sound_speed_paper_sum[k];
      const bool mean = phys.mass_definition == MassDefinition::mixture_mean;
      f.sound_speed[k] = mean ? f.sound_speed_mixture_mean[k] : f.sound_speed_paper_sum[k];
      f.mach[k] = mean ? f.mach_mixture_mean[k] : f.mach_paper_sum[k];
    }
  }
  return f;
}

std::vector<BinFields::Named> BinFields::named(const std::vector<std::string>& names) const {
  std::vector<Named> out = {
      {"particle_samples", "",
       "particles counted in the bin over all samples (the masking statistic)", &particle_samples},
      {"mean_count", "", "time-averaged number of particles in the bin", &mean_count},
      {"n", "m-2", "number density (per unit area)", &n},
      {"rho", "kg m-2", "mass density varrho = sum_a m_a n_a (per unit area)", &rho},
      {"phi", "", "area fraction sum_a n_a pi d_a^2 / 4", &phi},
      {"ux", "m s-1", "mass-averaged velocity, x", &ux},
      {"uy", "m s-1", "mass-averaged velocity, y (streamwise)", &uy},
      {"speed", "m s-1", "|u|", &speed},
      {"T", "J", "mixture granular temperature sum_a xi_a T_a", &temperature},
      {"T_norm", "", "T / (m_av U^2), m_av = sum_a m_a / n_species", &temperature_norm},
      {"P_kin_xx", "N m-1", "kinetic pressure tensor sum_a m_a <(c-u)(c-u)> n_a, xx", &p_kin_xx},
      {"P_kin_xy", "N m-1", "kinetic pressure tensor, xy", &p_kin_xy},
      {"P_kin_yy", "N m-1", "kinetic pressure tensor, yy", &p_kin_yy},
      {"P_col_xx", "N m-1", "collisional pressure tensor <W>/V_bin (compression positive), xx",
       &p_col_xx},
      {"P_col_xy", "N m-1", "collisional pressure tensor, xy", &p_col_xy},
      {"P_col_yx", "N m-1", "collisional pressure tensor, yx", &p_col_yx},
      {"P_col_yy", "N m-1", "collisional pressure tensor, yy", &p_col_yy},
      {"pressure", "N m-1", "tr(P_kin + P_col) / Dim", &pressure},
      {"pressure_eos", "N m-1", "n T (1 + (Dim-1)(1+e) phi g(phi))", &pressure_eos},
      {"eos_deviation", "", "pressure / pressure_eos - 1", &eos_deviation},
      {"a", "m s-1", "sound speed, the scene's mass definition", &sound_speed},
      {"Ma", "", "|u| / a, the scene's mass definition", &mach},
      {"a_mixture_mean", "m s-1", "sound speed with m = sum_a xi_a m_a", &sound_speed_mixture_mean},
      {"Ma_mixture_mean", "", "Mach number with m = sum_a xi_a m_a", &mach_mixture_mean},
      {"a_paper_sum", "m s-1", "sound speed with m = sum_a m_a (the paper's eq. 7)",
       &sound_speed_paper_sum},
      {"Ma_paper_sum", "", "Mach number with m = sum_a m_a", &mach_paper_sum},
  };
  for (std::size_t a = 0; a < names.size() && a < species_n.size(); ++a) {
    out.push_back({"n_" + names[a], "m-2", "number density of species " + names[a], &species_n[a]});
    out.push_back({"ux_" + names[a], "m s-1", "mean velocity of species " + names[a] + ", x",
                   &species_ux[a]});
    out.push_back({"uy_" + names[a], "m s-1", "mean velocity of species " + names[a] + ", y",
                   &species_uy[a]});
    out.push_back({"T_" + names[a], "J", "species temperature m_a <|c_a - u|^2> / Dim",
                   &species_temperature[a]});
  }
  if (dim == 3) {
    // Per volume of the bins' columns, not per area; the pressures force per area.
    for (Named& named : out) {
      if (named.unit == "m-2") named.unit = "m-3";
      if (named.unit == "kg m-2") named.unit = "kg m-3";
      if (named.unit == "N m-1") named.unit = "N m-2";
      if (named.name == "phi") named.description = "volume fraction sum_a n_a pi d_a^3 / 6";
    }
  }
  return out;
}

}  // namespace granshock

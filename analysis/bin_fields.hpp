// Per-bin fields from the accumulated sums (docs/fields.md; the paper's eqs. 3-8). With S
// the samples, V the bin area and, per species a, N_a = sum of counts, C_a = sum of
// velocities and K_a = sum of c (x) c over all samples:
//   n_a = N_a / (S V),  varrho_a = m_a n_a,  phi = sum_a n_a pi d_a^2 / 4
//   u_a = C_a / N_a,    u = sum_a m_a C_a / sum_a m_a N_a          (mass-averaged)
//   Q_a = K_a - u (x) C_a - C_a (x) u + N_a u (x) u  = sum of (c - u) (x) (c - u)
//   T_a = m_a tr Q_a / (Dim N_a),  T = sum_a xi_a T_a = sum_a m_a tr Q_a / (Dim N)
//   P_kin = sum_a m_a Q_a / (S V),  P_col = W / (S V),  p = tr(P_kin + P_col) / Dim
//   a = sqrt(T/m K(phi)), Ma = |u| / a, T* = T / (m_av U^2)
// P is the pressure tensor (compression positive; the Cauchy stress is -P): W is the
// summed contact virial sum 1/2 r_ij (x) F_ij with r_ij = x_i - x_j and F_ij the force on
// i, positive for repulsion, so that -W/(S V) is the collisional Cauchy stress of
// core/bin_layout.hpp. Masking: see MaskRule. Formulas and outputs: docs/fields.md.
#pragma once

#include <string>
#include <vector>

#include "analysis/field_physics.hpp"
#include "core/bin_sums.hpp"

namespace granshock {

// A bin is masked when fewer than min_particle_samples particles were counted in it over
// all samples (sum_a N_a < 20: an average below one particle in every few samples gives
// no usable velocity or temperature), or when its temperature is not resolved above zero.
// T comes from sum m (c - u)^2 = sum m c^2 - N m u^2, a difference of two sums of
// particle samples: when the velocities hardly fluctuate (one particle in free flight,
// sampled hundreds of times as it crosses a wake bin) it is their rounding error, of
// either sign, and Ma = |u|/a becomes 10^7 or infinite. T counts as resolved only above
// roundoff_factor N eps sum m c^2 (docs/fields.md, "Masking"). Masked bins hold NaN in
// every velocity, temperature, stress and Mach field; number densities and phi are kept
// wherever the bin was sampled (an empty bin has phi = 0).
struct MaskRule {
  double min_particle_samples = 20;
  double roundoff_factor = 4;
};

// Whether sum m (c - u)^2 = `fluctuation`, computed from `samples` particle samples whose
// sum m c^2 is `kinetic`, lies above its rounding error (MaskRule).
bool temperature_resolved(double fluctuation, double kinetic, double samples, const MaskRule& rule);

struct BinFields {
  int nx = 0, ny = 0, n_species = 0;
  // 3: densities per volume of the bins' columns through the layer, T and the pressure
  // with their z parts (docs/fields.md, "Three dimensions"); the units named() gives follow.
  int dim = 2;
  // Every vector is [ny * nx], index iy * nx + ix.
  std::vector<double> particle_samples;               // sum_a N_a over all samples
  std::vector<double> mean_count;                     // <N> = sum_a N_a / S
  std::vector<double> n, rho, phi;                    // 1/m^2, kg/m^2, area fraction
  std::vector<double> ux, uy, speed;                  // m/s, mass-averaged
  std::vector<double> temperature, temperature_norm;  // J; T / (m_av U^2)
  std::vector<double> p_kin_xx, p_kin_xy, p_kin_yy;   // N/m (2-D pressure: force per length)
  std::vector<double> p_col_xx, p_col_xy, p_col_yx, p_col_yy;
  std::vector<double> pressure;           // tr(P_kin + P_col) / Dim
  std::vector<double> pressure_eos;       // n T F(phi) = n T (1 + (Dim - 1)(1 + e) phi g(phi))
  std::vector<double> eos_deviation;      // pressure / pressure_eos - 1
  std::vector<double> sound_speed, mach;  // with the scene's mass definition
  std::vector<double> sound_speed_mixture_mean, mach_mixture_mean;
  std::vector<double> sound_speed_paper_sum, mach_paper_sum;
  std::vector<int> masked;  // 1 = masked
  // Per species a, [a][bin]:
  std::vector<std::vector<double>> species_samples, species_n, species_ux, species_uy,
      species_temperature;

  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int iy, int ix) const { return static_cast<std::size_t>(iy) * nx + ix; }

  struct Named {
    std::string name, unit, description;
    const std::vector<double>* values;
  };
  // Every floating-point field with its output name, unit and meaning (fields.h5, XDMF).
  std::vector<Named> named(const std::vector<std::string>& species_names) const;
};

// The fields of the sums pooled over all blocks of `sums`.
BinFields compute_bin_fields(const BinSums& sums, const FieldPhysics& physics,
                             const MaskRule& rule = {});

}  // namespace granshock

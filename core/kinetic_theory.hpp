// Kinetic-theory relations of the paper's section 2 (docs/fields.md) for a granular gas
// of dimension Dim with area (2-D) or volume fraction (3-D) phi and restitution e:
//   g(phi) = (16 - 7 phi) / (16 (1 - phi)^2)                (Henderson 1975, 2-D disks)
//   g(phi) = (1 - phi/2) / (1 - phi)^3                       (Carnahan & Starling 1969, spheres)
//   F(phi) = 1 + (Dim - 1)(1 + e) phi g(phi)
//   a      = sqrt( T/m (1 + (2/Dim) F + (phi/F) dF/dphi) F )  (adiabatic sound speed)
#pragma once

#include <string>
#include <vector>

namespace granshock {

// g(phi) at contact, and dg/dphi: (25 - 7 phi) / (16 (1 - phi)^3) for disks,
// (5/2 - phi) / (1 - phi)^4 for spheres. Dim is 2 or 3.
double radial_distribution(double phi, int dim);
double radial_distribution_slope(double phi, int dim);
double pressure_factor(double phi, double e, int dim);        // F
double pressure_factor_slope(double phi, double e, int dim);  // dF/dphi
// a^2 / (T/m): the dimensionless factor (1 + (2/Dim) F + (phi/F) F') F.
double sound_speed_factor(double phi, double e, int dim);
double sound_speed(double temperature, double mass, double phi, double e, int dim);

// Which mass m enters a = sqrt(T/m ...) for a mixture. The paper writes m = sum_a m_a;
// the mixture's mean mass sum_a xi_a m_a is what the single-species theory becomes
// for a mixture of equal particles, and it is granshock's default.
enum class MassDefinition { mixture_mean, paper_sum };
MassDefinition parse_mass_definition(const std::string& name);  // core/choice_names.hpp
std::string to_string(MassDefinition m);
double sound_speed_mass(MassDefinition def, const std::vector<double>& masses,
                        const std::vector<double>& number_fractions);

// The velocity fluctuation sigma (per component) that gives upstream Mach number
// `mach` at mean speed U: with T_a = m_a sigma^2 for every species, T = m_mean sigma^2,
// so sigma^2 = (U/Ma)^2 m / (m_mean * sound_speed_factor).
double sigma_for_mach(double mach, double speed, double phi, double e, int dim, double m_sound,
                      double m_mean);

}  // namespace granshock

#include "core/kinetic_theory.hpp"

#include <cmath>
#include <stdexcept>

#include "core/choice_names.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {
void check_dimension(int dim) {
  if (dim != 2 && dim != 3)
    throw std::invalid_argument("kinetic theory: dimension " + std::to_string(dim) +
                                " (2 or 3 expected)");
}
}  // namespace

double radial_distribution(double phi, int dim) {
  check_dimension(dim);
  const double hole = 1 - phi;
  if (dim == 3) return (1.0 - 0.5 * phi) / (hole * hole * hole);
  return (16.0 - 7.0 * phi) / (16.0 * hole * hole);
}

double radial_distribution_slope(double phi, int dim) {
  check_dimension(dim);
  const double hole = 1 - phi;
  if (dim == 3) return (2.5 - phi) / (hole * hole * hole * hole);
  return (25.0 - 7.0 * phi) / (16.0 * hole * hole * hole);
}

double pressure_factor(double phi, double e, int dim) {
  return 1.0 + (dim - 1) * (1.0 + e) * phi * radial_distribution(phi, dim);
}

double pressure_factor_slope(double phi, double e, int dim) {
  return (dim - 1) * (1.0 + e) *
         (radial_distribution(phi, dim) + phi * radial_distribution_slope(phi, dim));
}

double sound_speed_factor(double phi, double e, int dim) {
  const double f = pressure_factor(phi, e, dim);
  return (1.0 + 2.0 / dim * f + phi / f * pressure_factor_slope(phi, e, dim)) * f;
}

double sound_speed(double temperature, double mass, double phi, double e, int dim) {
  return std::sqrt(temperature / mass * sound_speed_factor(phi, e, dim));
}

MassDefinition parse_mass_definition(const std::string& name) {
  return parse_choice<MassDefinition>(name);
}

std::string to_string(MassDefinition m) {
  return choice_name(m);
}

double sound_speed_mass(MassDefinition def, const std::vector<double>& masses,
                        const std::vector<double>& xi) {
  double m = 0;
  for (std::size_t a = 0; a < masses.size(); ++a)
    m += def == MassDefinition::paper_sum ? masses[a] : xi.at(a) * masses[a];
  return m;
}

double sigma_for_mach(double mach, double speed, double phi, double e, int dim, double m_sound,
                      double m_mean) {
  const double a = speed / mach;
  return a * std::sqrt(m_sound / (m_mean * sound_speed_factor(phi, e, dim)));
}

}  // namespace granshock

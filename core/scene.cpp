#include "core/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/choice_names.hpp"

namespace granshock {

long Scene::total_steps() const {
  return long(std::llround(run.duration_s / setup.dt));
}

double Scene::fastest_impact_speed() const {
  return 2.0 * (inflow.speed_m_per_s + 4.0 * inflow.sigma);
}

double Scene::mean_mass() const {
  double m = 0;
  for (std::size_t a = 0; a < setup.species.size(); ++a)
    m += inflow.number_fraction[a] * setup.species[a].mass_kg();
  return m;
}

double Scene::mean_restitution() const {
  double e = 0;
  const auto& xi = inflow.number_fraction;
  for (std::size_t a = 0; a < xi.size(); ++a)
    for (std::size_t b = 0; b < xi.size(); ++b)
      e += xi[a] * xi[b] * setup.contacts.restitution[a][b];
  return e;
}

double Scene::mean_particle_measure() const {
  double measure = 0;
  for (std::size_t a = 0; a < setup.species.size(); ++a) {
    const double xi = inflow.number_fraction[a], d = setup.species[a].diameter_m;
    measure += setup.dim == 3 ? xi * M_PI * std::pow(d, 3) / 6 : xi * M_PI * std::pow(d, 2) / 4;
  }
  return measure;
}

double Scene::mean_particle_diameter() const {
  double d2 = 0;
  for (std::size_t a = 0; a < setup.species.size(); ++a)
    d2 += inflow.number_fraction[a] * std::pow(setup.species[a].diameter_m, 2);
  return std::sqrt(d2);
}

double Scene::depth() const {
  return setup.dim == 3 ? setup.box.length(2) : 1.0;
}

double Scene::inflow_number_per_area() const {
  return inflow.area_fraction * depth() / mean_particle_measure();
}

double Scene::capacity_unbounded() const {
  const double area = setup.box.length(0) * setup.box.length(1);
  return 1.5 * inflow_number_per_area() * area + 1024;
}

std::size_t Scene::capacity_estimate() const {
  // Bounded so that the conversion is defined; run_checks.cpp refuses scenes near it.
  return std::size_t(std::min(capacity_unbounded(), 1e15));
}

MachReference parse_mach_reference(const std::string& name) {
  return parse_choice<MachReference>(name);
}

std::string to_string(MachReference m) {
  return choice_name(m);
}

double Scene::sigma_at_mach(double mach) const {
  std::vector<double> masses;
  for (const auto& sp : setup.species) masses.push_back(sp.mass_kg());
  const double m_sound = sound_speed_mass(mass_definition, masses, inflow.number_fraction);
  return sigma_for_mach(mach, inflow.speed_m_per_s, inflow.area_fraction, mean_restitution(),
                        setup.dim, m_sound, mean_mass());
}

double Scene::inflow_mach() const {
  if (inflow.target_mach) return *inflow.target_mach;
  return inflow.sigma > 0 ? sigma_at_mach(1.0) / inflow.sigma : 0.0;
}

void resolve_inflow(Scene& s) {
  s.inflow.sigma =
      s.inflow.sigma_m_per_s ? *s.inflow.sigma_m_per_s : s.sigma_at_mach(*s.inflow.target_mach);
}

}  // namespace granshock

#include "core/solver_setup.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/choice_names.hpp"

namespace granshock {

ContactModelKind parse_contact_model(const std::string& name) {
  return parse_choice<ContactModelKind>(name);
}

std::string to_string(ContactModelKind model) {
  return choice_name(model);
}

RestitutionMode parse_restitution_mode(const std::string& name) {
  return parse_choice<RestitutionMode>(name);
}

std::string to_string(RestitutionMode mode) {
  return choice_name(mode);
}

ContactSettings ContactSettings::uniform(int n, double e, double mu) {
  ContactSettings m;
  m.restitution.assign(n, std::vector<double>(n, e));
  m.friction.assign(n, std::vector<double>(n, mu));
  m.obstacle_restitution.assign(n, e);
  m.obstacle_friction.assign(n, mu);
  return m;
}

ContactSettings ContactSettings::of_species(const std::vector<int>& kept) const {
  ContactSettings out;
  out.model = model;
  out.options = options;
  out.restitution_mode = restitution_mode;
  out.calibration_speed_m_per_s = calibration_speed_m_per_s;
  out.softening = softening;
  const auto square = [&](const std::vector<std::vector<double>>& from) {
    std::vector<std::vector<double>> to;
    for (const int a : kept) {
      to.emplace_back();
      for (const int b : kept) to.back().push_back(from.at(a).at(b));
    }
    return to;
  };
  const auto row = [&](const std::vector<double>& from) {
    std::vector<double> to;
    for (const int a : kept) to.push_back(from.at(a));
    return to;
  };
  out.restitution = square(restitution);
  out.friction = square(friction);
  out.obstacle_restitution = row(obstacle_restitution);
  out.obstacle_friction = row(obstacle_friction);
  if (!calibrated_beta.empty()) out.calibrated_beta = square(calibrated_beta);
  if (!obstacle_calibrated_beta.empty())
    out.obstacle_calibrated_beta = row(obstacle_calibrated_beta);
  return out;
}

bool ContactSettings::has_friction() const {
  for (const auto& row : friction)
    for (double mu : row)
      if (mu > 0) return true;
  return std::any_of(obstacle_friction.begin(), obstacle_friction.end(),
                     [](double mu) { return mu > 0; });
}

double SolverSetup::max_diameter() const {
  double d = 0;
  for (const auto& s : species) d = std::max(d, s.diameter_m);
  return d;
}

PairProperties SolverSetup::pair(int a, int b) const {
  PairProperties p =
      softened(particle_pair(species.at(a), species.at(b), contacts.restitution.at(a).at(b),
                             contacts.friction.at(a).at(b)),
               contacts.softening);
  if (!contacts.calibrated_beta.empty()) p.beta = contacts.calibrated_beta.at(a).at(b);
  return p;
}

PairProperties SolverSetup::obstacle_pair(int a) const {
  if (!obstacle) throw std::logic_error("obstacle_pair: the scene has no obstacle");
  PairProperties p = softened(
      particle_obstacle(species.at(a), obstacle->material, contacts.obstacle_restitution.at(a),
                        contacts.obstacle_friction.at(a)),
      contacts.softening);
  if (!contacts.obstacle_calibrated_beta.empty()) p.beta = contacts.obstacle_calibrated_beta.at(a);
  return p;
}

PairProperties SolverSetup::wall_pair(int a) const {
  if (!z_walls) throw std::logic_error("wall_pair: the scene has no walls");
  PairProperties p = softened(
      particle_obstacle(species.at(a), wall_material, contacts.obstacle_restitution.at(a), 0.0),
      contacts.softening);
  if (!contacts.obstacle_calibrated_beta.empty()) p.beta = contacts.obstacle_calibrated_beta.at(a);
  return p;
}

std::vector<PairProperties> SolverSetup::all_pairs() const {
  std::vector<PairProperties> pairs;
  const int n = int(species.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a; b < n; ++b) pairs.push_back(pair(a, b));
    if (obstacle) pairs.push_back(obstacle_pair(a));
    // Walls of another material than the obstacle's (a scene's are of its material).
    if (z_walls && (!obstacle || obstacle->material.name != wall_material.name))
      pairs.push_back(wall_pair(a));
  }
  return pairs;
}

}  // namespace granshock

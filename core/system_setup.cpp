#include "system_setup.hpp"

#include <algorithm>
#include <stdexcept>

namespace granshock {

ContactModel ContactModel::uniform(int n, double e, double mu) {
  ContactModel m;
  m.restitution.assign(n, std::vector<double>(n, e));
  m.friction.assign(n, std::vector<double>(n, mu));
  m.wall_restitution.assign(n, e);
  m.wall_friction.assign(n, mu);
  return m;
}

bool ContactModel::has_friction() const {
  for (const auto& row : friction)
    for (double mu : row)
      if (mu > 0) return true;
  return std::any_of(wall_friction.begin(), wall_friction.end(), [](double mu) { return mu > 0; });
}

double SystemSetup::max_diameter() const {
  double d = 0;
  for (const auto& s : species) d = std::max(d, s.diameter_m);
  return d;
}

PairProperties SystemSetup::pair(int a, int b) const {
  return particle_pair(species.at(a), species.at(b), contacts.restitution.at(a).at(b),
                       contacts.friction.at(a).at(b));
}

PairProperties SystemSetup::wall_pair(int a) const {
  if (!obstacle) throw std::logic_error("wall_pair: the scene has no obstacle");
  return particle_wall(species.at(a), obstacle->material, contacts.wall_restitution.at(a),
                       contacts.wall_friction.at(a));
}

std::vector<PairProperties> SystemSetup::all_pairs() const {
  std::vector<PairProperties> pairs;
  const int n = int(species.size());
  for (int a = 0; a < n; ++a) {
    for (int b = a; b < n; ++b) pairs.push_back(pair(a, b));
    if (obstacle) pairs.push_back(wall_pair(a));
  }
  return pairs;
}

}  // namespace granshock

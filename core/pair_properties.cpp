#include "core/pair_properties.hpp"

#include <algorithm>
#include <cmath>

namespace granshock {

double damping_beta(double e) {
  const double l = std::log(e);
  return l / std::sqrt(l * l + M_PI * M_PI);
}

namespace {
double inv_youngs(const Material& m) {
  return (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus_pa;
}
double inv_shear(const Material& m) {
  return 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.youngs_modulus_pa;
}
}  // namespace

PairProperties particle_pair(const Species& a, const Species& b, double e, double mu) {
  PairProperties p;
  p.name = a.name + "-" + b.name;
  p.youngs_star = 1.0 / (inv_youngs(a.material) + inv_youngs(b.material));
  p.shear_star = 1.0 / (inv_shear(a.material) + inv_shear(b.material));
  p.radius_star = 1.0 / (1.0 / a.radius_m() + 1.0 / b.radius_m());
  p.mass_star = 1.0 / (1.0 / a.mass_kg() + 1.0 / b.mass_kg());
  p.min_diameter = std::min(a.diameter_m, b.diameter_m);
  p.beta = damping_beta(e);
  p.restitution = e;
  p.friction = mu;
  return p;
}

PairProperties softened(PairProperties p, double softening) {
  p.youngs_star /= softening;
  p.shear_star /= softening;
  return p;
}

PairProperties particle_obstacle(const Species& s, const Material& obstacle, double e, double mu) {
  PairProperties p;
  p.name = s.name + "-obstacle";
  p.youngs_star = 1.0 / (inv_youngs(s.material) + inv_youngs(obstacle));
  p.shear_star = 1.0 / (inv_shear(s.material) + inv_shear(obstacle));
  p.radius_star = s.radius_m();
  p.mass_star = s.mass_kg();
  p.min_diameter = s.diameter_m;
  p.beta = damping_beta(e);
  p.restitution = e;
  p.friction = mu;
  return p;
}

}  // namespace granshock

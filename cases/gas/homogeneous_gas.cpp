#include "cases/gas/homogeneous_gas.hpp"

#include <cmath>

#include "core/user_error.hpp"
#include "kernels/device/counter_rng.hpp"

namespace granshock {

namespace {
double mean_disk_area(const SolverSetup& s) {
  double a = 0;
  for (const auto& sp : s.species) a += M_PI * sp.diameter_m * sp.diameter_m / 4.0;
  return a / double(s.species.size());
}
int lattice_side(const GasSpec& spec) {
  return std::max(1, int(std::lround(std::sqrt(double(spec.particles)))));
}
}  // namespace

void size_periodic_box(SolverSetup& setup, const GasSpec& spec) {
  const int side = lattice_side(spec);
  const double area = double(side) * side * mean_disk_area(setup) / spec.area_fraction;
  const double length = std::sqrt(area);
  setup.box.lo = {0, 0, 0};
  setup.box.hi = {length, length, setup.max_diameter()};
  setup.box.periodic = {true, true, false};
}

HostParticles make_homogeneous_gas(const SolverSetup& setup, const GasSpec& spec) {
  const int side = lattice_side(spec);
  const double spacing = setup.box.length(0) / side;
  const double room = spacing - setup.max_diameter();
  if (room <= 0)
    throw UserError("area fraction " + std::to_string(spec.area_fraction) +
                    " is too dense for a square lattice of these particles");
  const CounterRng rng{spec.seed};
  const int n_species = int(setup.species.size());
  HostParticles p;
  for (int k = 0; k < side * side; ++k) {
    const int ix = k % side, iy = k / side;
    // Jitter keeps every pair at least one diameter apart: each centre stays within
    // room/2 of its lattice site.
    const double jx = (rng.uniform(k, 0) - 0.5) * room;
    const double jy = (rng.uniform(k, 1) - 0.5) * room;
    const std::array<double, 3> x{setup.box.lo[0] + (ix + 0.5) * spacing + jx,
                                  setup.box.lo[1] + (iy + 0.5) * spacing + jy, 0};
    const std::array<double, 3> v{spec.sigma_m_per_s * rng.normal(k, 1),
                                  spec.sigma_m_per_s * rng.normal(k, 2), 0};
    p.add(x, v, k % n_species, k);
  }
  // Remove the centre-of-mass velocity so the total momentum is zero.
  std::array<double, 2> momentum{0, 0};
  double mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = setup.species[p.species[i]].mass_kg();
    mass += m;
    for (int d = 0; d < 2; ++d) momentum[d] += m * p.velocity[i][d];
  }
  for (auto& v : p.velocity)
    for (int d = 0; d < 2; ++d) v[d] -= momentum[d] / mass;
  return p;
}

SolverSetup paper_mixture(double restitution) {
  SolverSetup s;
  s.species = {{"steel", steel(), 1e-3}, {"aluminium", aluminium(), 1e-3}};
  s.contacts = ContactSettings::uniform(2, restitution, 0.0);
  return s;
}

}  // namespace granshock

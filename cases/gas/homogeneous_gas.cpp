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
double mean_sphere_volume(const SolverSetup& s) {
  double v = 0;
  for (const auto& sp : s.species) v += M_PI * std::pow(sp.diameter_m, 3) / 6.0;
  return v / double(s.species.size());
}
int lattice_side(const GasSpec& spec, int dim) {
  const double n = double(spec.particles);
  return std::max(1, int(std::lround(dim == 3 ? std::cbrt(n) : std::sqrt(n))));
}
}  // namespace

void size_periodic_box(SolverSetup& setup, const GasSpec& spec) {
  const int side = lattice_side(spec, setup.dim);
  setup.box.lo = {0, 0, 0};
  if (setup.dim == 3) {
    const double volume =
        std::pow(double(side), 3) * mean_sphere_volume(setup) / spec.area_fraction;
    const double length = std::cbrt(volume);
    setup.box.hi = {length, length, length};
    setup.box.periodic = {true, true, true};
    return;
  }
  const double area = double(side) * side * mean_disk_area(setup) / spec.area_fraction;
  const double length = std::sqrt(area);
  setup.box.hi = {length, length, setup.max_diameter()};
  setup.box.periodic = {true, true, false};
}

HostParticles make_homogeneous_gas(const SolverSetup& setup, const GasSpec& spec) {
  const int side = lattice_side(spec, setup.dim);
  const double spacing = setup.box.length(0) / side;
  const double room = spacing - setup.max_diameter();
  if (room <= 0)
    throw UserError((setup.dim == 3 ? "volume fraction " : "area fraction ") +
                    std::to_string(spec.area_fraction) + " is too dense for a " +
                    (setup.dim == 3 ? "cubic" : "square") + " lattice of these particles");
  const CounterRng rng{spec.seed};
  const int n_species = int(setup.species.size());
  HostParticles p;
  const int sites = setup.dim == 3 ? side * side * side : side * side;
  for (int k = 0; k < sites; ++k) {
    // Site k's cell along each axis; the jitter keeps every pair at least one diameter
    // apart: each centre stays within room/2 of its lattice site. Axis d draws uniform
    // number d and normal number d + 1 of stream k (z only in 3-D).
    std::array<double, 3> x{0, 0, 0}, v{0, 0, 0};
    for (int d = 0, stride = 1; d < setup.dim; ++d, stride *= side) {
      const int cell = (k / stride) % side;
      x[d] = setup.box.lo[d] + (cell + 0.5) * spacing + (rng.uniform(k, d) - 0.5) * room;
      v[d] = spec.sigma_m_per_s * rng.normal(k, d + 1);
    }
    p.add(x, v, k % n_species, k);
  }
  // Remove the centre-of-mass velocity so the total momentum is zero.
  std::array<double, 3> momentum{0, 0, 0};
  double mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = setup.species[p.species[i]].mass_kg();
    mass += m;
    for (int d = 0; d < setup.dim; ++d) momentum[d] += m * p.velocity[i][d];
  }
  for (auto& v : p.velocity)
    for (int d = 0; d < setup.dim; ++d) v[d] -= momentum[d] / mass;
  return p;
}

SolverSetup paper_mixture(double restitution) {
  SolverSetup s;
  s.species = {{"steel", steel(), 1e-3}, {"aluminium", aluminium(), 1e-3}};
  s.contacts = ContactSettings::uniform(2, restitution, 0.0);
  return s;
}

}  // namespace granshock

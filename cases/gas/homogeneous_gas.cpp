#include "cases/gas/homogeneous_gas.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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

// Random sequential addition of `count` particles (species k % n_species) into the
// periodic box: candidate t draws uniform numbers 0..dim-1 of stream t of its own
// generator, and is kept when it overlaps no particle kept before it. A grid of cells at
// least one largest diameter wide finds the particles that could overlap.
std::vector<std::array<double, 3>> random_positions(const SolverSetup& setup, const GasSpec& spec,
                                                    int count) {
  const int dim = setup.dim, n_species = int(setup.species.size());
  const CounterRng draw{spec.seed ^ 0x5253410000000000ULL};  // "RSA": not the velocities' stream
  std::array<int, 3> cells{1, 1, 1};
  std::array<double, 3> length{0, 0, 0};
  for (int d = 0; d < dim; ++d) {
    length[d] = setup.box.length(d);
    cells[d] = std::max(1, int(length[d] / setup.max_diameter()));
  }
  const auto cell_of = [&](const std::array<double, 3>& x, int d) {
    return std::min(cells[d] - 1, int((x[d] - setup.box.lo[d]) / length[d] * cells[d]));
  };
  // Each cell's particles as a linked list (first[cell], then next[k]): at 2M particles
  // of a dilute gas the cells are 16M, too many for a vector each.
  const std::size_t cell_count = std::size_t(cells[0]) * std::size_t(cells[1] * cells[2]);
  std::vector<int> first(cell_count, -1), next;
  const auto index = [&](int cx, int cy, int cz) {
    return (std::size_t(cz) * cells[1] + cy) * cells[0] + cx;
  };
  next.reserve(std::size_t(count));
  std::vector<std::array<double, 3>> x;
  x.reserve(std::size_t(count));
  const std::uint64_t attempts = 1000 * std::uint64_t(count);
  for (std::uint64_t t = 0; int(x.size()) < count; ++t) {
    if (t == attempts)
      throw UserError((dim == 3 ? "volume fraction " : "area fraction ") +
                      std::to_string(spec.area_fraction) +
                      " is too dense for random placement (it jams near " +
                      (dim == 3 ? "0.38" : "0.55") + "): place the gas on the lattice");
    const int k = int(x.size());
    std::array<double, 3> c{0, 0, 0};
    for (int d = 0; d < dim; ++d)
      c[d] = setup.box.lo[d] + draw.uniform(t, std::uint64_t(d)) * length[d];
    const double rk = setup.species[std::size_t(k % n_species)].radius_m();
    // Along each axis the cells within one of c's: from the one below, three of them, or
    // all where the axis has fewer than three (each once).
    std::array<int, 3> at{0, 0, 0}, low{0, 0, 0}, span{1, 1, 1};
    for (int d = 0; d < dim; ++d) {
      at[d] = cell_of(c, d);
      span[d] = std::min(3, cells[d]);
      low[d] = cells[d] < 3 ? 0 : at[d] - 1 + cells[d];
    }
    const auto cell = [&](int d, int o) { return (low[d] + o) % cells[d]; };
    bool free = true;
    for (int oz = 0; oz < span[2]; ++oz)
      for (int oy = 0; oy < span[1]; ++oy)
        for (int ox = 0; ox < span[0]; ++ox)
          for (int j = first[index(cell(0, ox), cell(1, oy), cell(2, oz))]; j >= 0;
               j = next[std::size_t(j)]) {
            double r2 = 0;
            for (int d = 0; d < dim; ++d) {
              double dx = c[d] - x[std::size_t(j)][d];
              dx -= length[d] * std::round(dx / length[d]);  // minimum image
              r2 += dx * dx;
            }
            const double reach = rk + setup.species[std::size_t(j % n_species)].radius_m();
            free = free && r2 >= reach * reach;
          }
    if (!free) continue;
    int& head = first[index(at[0], at[1], at[2])];
    next.push_back(head);
    head = k;
    x.push_back(c);
  }
  return x;
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
  const bool random = spec.placement == GasPlacement::random;
  if (room <= 0 && !random)
    throw UserError((setup.dim == 3 ? "volume fraction " : "area fraction ") +
                    std::to_string(spec.area_fraction) + " is too dense for a " +
                    (setup.dim == 3 ? "cubic" : "square") + " lattice of these particles");
  const CounterRng rng{spec.seed};
  const int n_species = int(setup.species.size());
  HostParticles p;
  const int sites = setup.dim == 3 ? side * side * side : side * side;
  const std::vector<std::array<double, 3>> placed =
      random ? random_positions(setup, spec, sites) : std::vector<std::array<double, 3>>{};
  for (int k = 0; k < sites; ++k) {
    // Site k's cell along each axis; the jitter keeps every pair at least one diameter
    // apart: each centre stays within room/2 of its lattice site. Axis d draws uniform
    // number d and normal number d + 1 of stream k (z only in 3-D).
    std::array<double, 3> x{0, 0, 0}, v{0, 0, 0};
    for (int d = 0, stride = 1; d < setup.dim; ++d, stride *= side) {
      const int cell = (k / stride) % side;
      x[d] = random ? placed[std::size_t(k)][d]
                    : setup.box.lo[d] + (cell + 0.5) * spacing + (rng.uniform(k, d) - 0.5) * room;
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

// Per-species and per-pair constants on the device, built once from a SystemSetup.
#pragma once

#include <Kokkos_Core.hpp>

#include "pair_properties.hpp"
#include "system_setup.hpp"

namespace granshock {

template <class Real, class MemSpace>
struct SpeciesTable {
  Kokkos::View<Real*, MemSpace> radius;
  Kokkos::View<Real*, MemSpace> inv_mass;
  Kokkos::View<Real*, MemSpace> inv_inertia;
  Kokkos::View<HertzCoefficients<Real>**, MemSpace> pair;  // [species_i][species_j]
  Kokkos::View<HertzCoefficients<Real>*, MemSpace> wall;   // [species] vs obstacle
  double mass_host[64] = {};                               // for host-side diagnostics

  static SpeciesTable build(const SystemSetup& s) {
    const int n = int(s.species.size());
    SpeciesTable t;
    t.radius = decltype(t.radius)("radius", n);
    t.inv_mass = decltype(t.inv_mass)("inv_mass", n);
    t.inv_inertia = decltype(t.inv_inertia)("inv_inertia", n);
    t.pair = decltype(t.pair)("pair_coefficients", n, n);
    t.wall = decltype(t.wall)("wall_coefficients", n);
    auto radius = Kokkos::create_mirror_view(t.radius);
    auto inv_mass = Kokkos::create_mirror_view(t.inv_mass);
    auto inv_inertia = Kokkos::create_mirror_view(t.inv_inertia);
    auto pair = Kokkos::create_mirror_view(t.pair);
    auto wall = Kokkos::create_mirror_view(t.wall);
    for (int a = 0; a < n; ++a) {
      radius(a) = Real(s.species[a].radius_m());
      inv_mass(a) = Real(1.0 / s.species[a].mass_kg());
      inv_inertia(a) = Real(1.0 / s.species[a].moment_of_inertia());
      for (int b = 0; b < n; ++b)
        pair(a, b) = hertz_coefficients<Real>(s.pair(a, b), s.contacts.limit_force);
      if (s.obstacle) wall(a) = hertz_coefficients<Real>(s.wall_pair(a), s.contacts.limit_force);
    }
    Kokkos::deep_copy(t.radius, radius);
    Kokkos::deep_copy(t.inv_mass, inv_mass);
    Kokkos::deep_copy(t.inv_inertia, inv_inertia);
    Kokkos::deep_copy(t.pair, pair);
    Kokkos::deep_copy(t.wall, wall);
    return t;
  }
};

}  // namespace granshock

// Per-species and per-pair constants on the device, built once from a SolverSetup: radii,
// inverse masses and moments of inertia, and the contact law's coefficients for every pair
// of species and for every species against the obstacle and a slab's walls
// (Model::coefficients).
#pragma once

#include <Kokkos_Core.hpp>

#include "core/solver_setup.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/models/clamped_normal.hpp"

namespace granshock {

template <class Model, class Real, class MemSpace>
struct PairTable {
  using Coefficients = typename Model::template Coefficients<Real>;

  Kokkos::View<Real*, MemSpace> radius;
  Kokkos::View<Real*, MemSpace> inv_mass;
  Kokkos::View<Real*, MemSpace> inv_inertia;
  Kokkos::View<Coefficients**, MemSpace> pair;     // [species_i][species_j]
  Kokkos::View<Coefficients*, MemSpace> obstacle;  // [species] against the obstacle
  Kokkos::View<Coefficients*, MemSpace> wall;      // [species] against a slab's walls
  // The floor of every normal force (models/clamped_normal.hpp): contact.limit_force.
  Real normal_force_floor = 0;

  // Paths: the caller's (device/host_mirror.hpp).
  template <class Paths>
  static PairTable build(const SolverSetup& s) {
    const int n = int(s.species.size());
    PairTable t;
    t.radius = decltype(t.radius)("radius", n);
    t.inv_mass = decltype(t.inv_mass)("inv_mass", n);
    t.inv_inertia = decltype(t.inv_inertia)("inv_inertia", n);
    t.pair = decltype(t.pair)("pair_coefficients", n, n);
    t.obstacle = decltype(t.obstacle)("obstacle_coefficients", n);
    t.wall = decltype(t.wall)("wall_coefficients", n);
    auto radius = host_mirror<Paths>(t.radius);
    auto inv_mass = host_mirror<Paths>(t.inv_mass);
    auto inv_inertia = host_mirror<Paths>(t.inv_inertia);
    auto pair = host_mirror<Paths>(t.pair);
    auto obstacle = host_mirror<Paths>(t.obstacle);
    auto wall = host_mirror<Paths>(t.wall);
    const ContactOptions& o = s.contacts.options;
    t.normal_force_floor = granshock::normal_force_floor<Real>(o);
    for (int a = 0; a < n; ++a) {
      radius(a) = Real(s.species[a].radius_m());
      inv_mass(a) = Real(1.0 / s.species[a].mass_kg());
      inv_inertia(a) = Real(1.0 / s.species[a].moment_of_inertia());
      for (int b = 0; b < n; ++b) pair(a, b) = Model::template coefficients<Real>(s.pair(a, b), o);
      if (s.obstacle) obstacle(a) = Model::template coefficients<Real>(s.obstacle_pair(a), o);
      if (s.z_walls) wall(a) = Model::template coefficients<Real>(s.wall_pair(a), o);
    }
    Kokkos::deep_copy(t.radius, radius);
    Kokkos::deep_copy(t.inv_mass, inv_mass);
    Kokkos::deep_copy(t.inv_inertia, inv_inertia);
    Kokkos::deep_copy(t.pair, pair);
    Kokkos::deep_copy(t.obstacle, obstacle);
    Kokkos::deep_copy(t.wall, wall);
    return t;
  }
};

}  // namespace granshock

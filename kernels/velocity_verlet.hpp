// Velocity-Verlet integration (as LIGGGHTS fix nve/sphere), split in its two halves:
//   first half:  v += dt/2 (f/m + g);  x += dt v;  (w += dt/2 tau/I with friction)
//   second half: v += dt/2 (f/m + g);              (w += dt/2 tau/I with friction)
// Forces between the halves see positions at t + dt and velocities at t + dt/2.
#pragma once

#include <Kokkos_Core.hpp>

#include "device_lambda.hpp"
#include "particle_store.hpp"
#include "species_table.hpp"
#include "vec.hpp"

namespace granshock {

template <class Traits, class ExecSpace>
struct VelocityVerlet {
  static constexpr int Dim = Traits::dim;
  using Real = typename Traits::real;
  using Mem = typename ExecSpace::memory_space;
  using Policy = Kokkos::RangePolicy<ExecSpace>;

  Real dt;
  Vec<Dim, Real> gravity;

  // First half step. Returns the largest squared displacement from x_ref, the positions
  // at the last neighbour-list build, which decides whether the list is still valid.
  Real first_half(const ParticleStore<Dim, Real, Mem>& p, const SpeciesTable<Real, Mem>& table,
                  const Kokkos::View<Real* [Dim], Mem>& x_ref) const {
    const Real half = Real(0.5) * dt, step = dt;
    const auto g = gravity;
    const auto x = p.x, v = p.v, f = p.f;
    const auto omega = p.omega, torque = p.torque;
    const auto species = p.species;
    const auto inv_mass = table.inv_mass, inv_inertia = table.inv_inertia;
    Real max_d2 = 0;
    Kokkos::parallel_reduce(
        "verlet::first_half", Policy(0, p.n),
        KOKKOS_LAMBDA(const int i, Real& worst) {
          capture_before_if_constexpr(omega, torque, inv_inertia);
          const int s = species(i);
          const Real im = inv_mass(s);
          Real d2 = 0;
          for (int d = 0; d < Dim; ++d) {
            v(i, d) += half * (f(i, d) * im + g[d]);
            x(i, d) += step * v(i, d);
            const Real moved = x(i, d) - x_ref(i, d);
            d2 += moved * moved;
          }
          if constexpr (Traits::friction) omega(i) += half * torque(i) * inv_inertia(s);
          if (d2 > worst) worst = d2;
        },
        Kokkos::Max<Real>(max_d2));
    return max_d2;
  }

  void second_half(const ParticleStore<Dim, Real, Mem>& p,
                   const SpeciesTable<Real, Mem>& table) const {
    const Real half = Real(0.5) * dt;
    const auto g = gravity;
    const auto v = p.v, f = p.f;
    const auto omega = p.omega, torque = p.torque;
    const auto species = p.species;
    const auto inv_mass = table.inv_mass, inv_inertia = table.inv_inertia;
    Kokkos::parallel_for(
        "verlet::second_half", Policy(0, p.n), KOKKOS_LAMBDA(const int i) {
          capture_before_if_constexpr(omega, torque, inv_inertia);
          const int s = species(i);
          const Real im = inv_mass(s);
          for (int d = 0; d < Dim; ++d) v(i, d) += half * (f(i, d) * im + g[d]);
          if constexpr (Traits::friction) omega(i) += half * torque(i) * inv_inertia(s);
        });
  }
};

}  // namespace granshock

// Velocity-Verlet integration (as LIGGGHTS fix nve/sphere), split in its two halves:
//   first half:  v += dt/2 (f/m + g);  x += dt v;  (w += dt/2 tau/I with friction)
//   second half: v += dt/2 (f/m + g);              (w += dt/2 tau/I with friction)
// Forces between the halves see positions at t + dt and velocities at t + dt/2. This is
// the first half, which starts a call of advance(); the fused step does the second half
// of one step with the first of the next, and the closing pass the call's last second
// half (fused_step.hpp), with the same half_kick (kick.hpp).
// Positions are Position (double) in every variant: the drift adds a Real step dt v to a
// double position, and the displacement from x_ref is formed in double (device/position.hpp).
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/device_lambda.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/device/vec.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/solver/kick.hpp"
#include "kernels/solver/pair_table.hpp"

namespace granshock {

template <class V, class ExecSpace>
struct VelocityVerlet {
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Mem = typename Types::Mem;
  using Policy = typename Types::Policy;
  using Store = typename Types::Store;
  using Table = PairTable<typename Types::Model, Real, Mem>;

  Real dt;
  Vec<Dim, Real> gravity;

  // First half step. Returns the largest squared displacement from x_ref, the positions
  // at the last neighbour-list build, which decides whether the list is still valid
  // (a process-local maximum: the solver reduces it over processes).
  Real first_half(const Store& p, const Table& table) const {
    Real max_d2 = 0;
    first_half("verlet::first_half", p, table, Kokkos::Max<Real>(max_d2));
    return max_d2;
  }

  // The same, the largest squared displacement reduced by `largest`: into a host value as
  // above, or into a device View where device paths keep it for their watch
  // (chained_steps.hpp; the kernel's name then says so: launch_counter.hpp).
  template <class Reducer>
  void first_half(const char* name, const Store& p, const Table& table,
                  const Reducer& largest) const {
    const Real half = Real(0.5) * dt, step = dt;
    const auto g = gravity;
    const auto x = p.x, x_ref = p.x_ref;  // one type per auto declaration
    const auto v = p.v, f = p.f;
    const auto omega = p.omega, torque = p.torque;
    const auto species = p.species;
    const auto inv_mass = table.inv_mass, inv_inertia = table.inv_inertia;
    Kokkos::parallel_reduce(
        name, Policy(0, p.n),
        KOKKOS_LAMBDA(const int i, Real& worst) {
          capture_before_if_constexpr(omega, torque, inv_inertia);
          const int s = species(i);
          const Real im = inv_mass(s);
          Real d2 = 0;
          for (int d = 0; d < Dim; ++d) {
            half_kick(v(i, d), half, f(i, d), im, g[d]);
            x(i, d) += step * v(i, d);
            const Real moved = Real(x(i, d) - x_ref(i, d));
            d2 += moved * moved;
          }
          if constexpr (V::friction) {
            Spin<Dim, Real> w = load_spin<Dim>(omega, i);
            half_spin_kick(w, half, load_spin<Dim>(torque, i), inv_inertia(s));
            store_spin<Dim>(omega, i, w);
          }
          if (d2 > worst) worst = d2;
        },
        largest);
  }

  // The largest squared displacement from x_ref, as first_half() measures it, without
  // moving anything (for a rebuild check after a drift that reported speeds).
  Real largest_displacement2(const Store& p) const {
    const auto x = p.x, x_ref = p.x_ref;
    Real max_d2 = 0;
    Kokkos::parallel_reduce(
        "verlet::displacement", Policy(0, p.n),
        KOKKOS_LAMBDA(const int i, Real& worst) {
          Real d2 = 0;
          for (int d = 0; d < Dim; ++d) {
            const Real moved = Real(x(i, d) - x_ref(i, d));
            d2 += moved * moved;
          }
          if (d2 > worst) worst = d2;
        },
        Kokkos::Max<Real>(max_d2));
    return max_d2;
  }
};

}  // namespace granshock

// The force kernel: for each particle, the sum of its contacts with the partners of the
// pair loop and, when the scene has one, with the obstacle, by the variant's contact law
// (docs/design.md, "The force kernel"). Friction and obstacle are compile-time: a
// frictionless scene compiles no tangential force, history or torque; a scene without
// obstacle no obstacle contact. Each particle writes only its own force, torque and
// springs (full lists), so the kernel needs no atomics and its result does not depend on
// the thread count.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/row_element.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/device/vec.hpp"
#include "kernels/models/clamped_normal.hpp"
#include "kernels/models/tangential_spring.hpp"
#include "kernels/models/z_walls.hpp"
#include "kernels/neighbours/pair_loop.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/solver/pair_table.hpp"

namespace granshock {

// Mode: forces (the time step); forces_and_virial (the step's last pass: the forces as in
// `forces`, and per particle the contact virial W_i = sum_j 1/2 r_ij (x) F_ij of those very
// pair forces, r_ij = x_i - x_j, written to `virial` for field sampling: docs/fields.md,
// "The contact virial"); or virial alone (a sample with no such pass before it: forces,
// torques and contact history are left untouched, so sampling cannot change the trajectory).
enum class ForceMode { forces, forces_and_virial, virial };

template <class V, class ExecSpace, ForceMode Mode = ForceMode::forces>
struct ContactForceKernel {
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Model = typename Types::Model;
  using Mem = typename Types::Mem;
  using Store = typename Types::Store;
  using Obstacle = typename Types::Obstacle;
  using Position = typename Types::Position;  // of x: double (device/position.hpp)
  using SpinValue = Spin<Dim, Real>;          // about z in 2-D (device/spin.hpp)

  Store p;
  PairLoop<Dim, Real, Mem> pairs;
  PairTable<Model, Real, Mem> table;
  Obstacle obstacle;
  Real dt;
  Kokkos::View<int, Mem> history_overflow;       // set when slots run out
  Kokkos::View<Real * [Dim * Dim], Mem> virial;  // not in ForceMode::forces
  ZWalls walls;                                  // a 3-D slab's walls

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<Dim, Position> xi = pairs.position(i);
    const Vec<Dim, Real> vi = velocity(i);
    if constexpr (Mode == ForceMode::virial) {
      Real w[Dim * Dim] = {};
      Vec<Dim, Real> force = Vec<Dim, Real>::zero();
      SpinValue torque = zero_spin<Dim, Real>();
      int used_slots = 0;
      sum_contacts(i, xi, vi, force, torque, used_slots, w);
      for (int k = 0; k < Dim * Dim; ++k) virial(i, k) = w[k];
    } else if constexpr (Mode == ForceMode::forces_and_virial) {
      Vec<Dim, Real> force;
      SpinValue torque;
      Real w[Dim * Dim] = {};
      total(i, xi, vi, force, torque, w);
      store(i, force, torque);
      for (int k = 0; k < Dim * Dim; ++k) virial(i, k) = w[k];
    } else {
      Vec<Dim, Real> force;
      SpinValue torque;
      total(i, xi, vi, force, torque);
      store(i, force, torque);
    }
  }

  KOKKOS_FORCEINLINE_FUNCTION void store(int i, const Vec<Dim, Real>& force,
                                         const SpinValue& torque) const {
    for (int d = 0; d < Dim; ++d) p.f(i, d) = force[d];
    if constexpr (V::friction) store_spin<Dim>(p.torque, i, torque);
  }

  // Passed as vi to total(): particle i's own velocity is then read where a contact needs
  // it, not before the pair loop. The fused step (fused_step.hpp) passes it: most list
  // partners do not touch, and a velocity held past them took registers from the pair
  // loop, which then kept other values on the stack (docs/benchmarks.md, "Instructions
  // per particle-step"). The values are the same.
  struct ReadOwnVelocity {};
  KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> own_velocity(int, const Vec<Dim, Real>& vi) const {
    return vi;
  }
  KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> own_velocity(int i, ReadOwnVelocity) const {
    return velocity(i);
  }

  // The force and torque on particle i at xi with velocity vi (not ForceMode::virial): its
  // contacts, their springs (updated) and the obstacle; w, when given, gets the contacts'
  // virial (ForceMode::forces_and_virial). The fused step (fused_step.hpp) calls it
  // directly and keeps the result in registers, with WithObstacle false for a particle
  // known not to touch the obstacle and Images false for one known to have no partner
  // across a periodic face (run_marks.hpp).
  template <bool WithObstacle = V::obstacle::present, bool Images = true,
            class OwnVelocity = Vec<Dim, Real>>
  KOKKOS_FORCEINLINE_FUNCTION void total(int i, const Vec<Dim, Position>& xi, const OwnVelocity& vi,
                                         Vec<Dim, Real>& force, SpinValue& torque,
                                         Real* w = nullptr) const {
    force = Vec<Dim, Real>::zero();
    torque = zero_spin<Dim, Real>();
    int used_slots = 0;  // bit s set when slot s carried a contact this step
    sum_contacts<Images>(i, xi, vi, force, torque, used_slots, w);
    if constexpr (V::friction) release_unused_slots(i, used_slots);
    if constexpr (WithObstacle) {
      const int si = p.species(i);
      obstacle_contact(i, xi, own_velocity(i, vi), si, table.radius(si), force, torque);
    }
    if constexpr (Dim == 3)
      if (walls.on) wall_contacts(i, xi, own_velocity(i, vi), force);
  }

  // Sums the pair forces of i's contacts into force (and torque; w, the virial, unless in
  // ForceMode::forces); Images as in PairLoop::for_each_contact.
  template <bool Images = true, class OwnVelocity>
  KOKKOS_FORCEINLINE_FUNCTION void sum_contacts(int i, const Vec<Dim, Position>& xi,
                                                const OwnVelocity& vi, Vec<Dim, Real>& force,
                                                SpinValue& torque, int& used_slots, Real* w) const {
    pairs.template for_each_contact<Images>(
        i, xi, [&](int j, int sj, const Vec<Dim, Real>& dx, Real r2, Real rsum) {
          const int si = p.species(i);  // read per contact: most partners do not touch
          const Real ri = table.radius(si);
          const Real r = dmath::sqrt(r2);
          const Vec<Dim, Real> n = (Real(1) / r) * dx;
          const Vec<Dim, Real> vrel = own_velocity(i, vi) - velocity(j);
          const auto& c = table.pair(si, sj);
          const auto normal =
              clamped_normal<Model>(c, rsum - r, dot(vrel, n), table.normal_force_floor);
          Vec<Dim, Real> pair_force = normal.force * n;
          if constexpr (V::friction) {
            const int slot = Mode != ForceMode::virial ? claim_slot(i, p.id(j), used_slots)
                                                       : find_slot(i, p.id(j));
            const Vec<Dim, Real> vc = contact_point_velocity(
                vrel, n,
                ri * load_spin<Dim>(p.omega, i) + table.radius(sj) * load_spin<Dim>(p.omega, j));
            Vec<Dim, Real> xi_t = Vec<Dim, Real>::zero();
            if (slot >= 0)
              for (int d = 0; d < Dim; ++d) xi_t[d] = p.history_spring(i, Dim * slot + d);
            const Vec<Dim, Real> ft = friction(c, normal, n, vc, xi_t);
            if constexpr (Mode != ForceMode::virial) {
              if (slot >= 0)
                for (int d = 0; d < Dim; ++d) p.history_spring(i, Dim * slot + d) = xi_t[d];
              torque += contact_torque(ri, n, ft);
            }
            pair_force += ft;
          }
          force += pair_force;
          if constexpr (Mode != ForceMode::forces)
            for (int a = 0; a < Dim; ++a)
              for (int b = 0; b < Dim; ++b) w[a * Dim + b] += Real(0.5) * dx[a] * pair_force[b];
        });
  }

  // The tangential force of a contact with normal force `normal` (docs/contact_model.md,
  // "Tangential force"); advances the spring xi_t.
  template <class Coefficients, class Normal>
  KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> friction(const Coefficients& c, const Normal& normal,
                                                      const Vec<Dim, Real>& n,
                                                      const Vec<Dim, Real>& vc,
                                                      Vec<Dim, Real>& xi_t) const {
    const auto spring = Model::tangential(c, normal);
    return tangential_force(spring.kt, spring.gt, c.friction, normal.force, n, vc, dt, xi_t);
  }

  KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> velocity(int i) const {
    Vec<Dim, Real> r;
    for (int d = 0; d < Dim; ++d) r[d] = row_element(p.v, i, d);
    return r;
  }

  // Contact with the obstacle: its shape gives the overlap and the normal, the law the
  // force with the obstacle coefficients (R* = r_i, m* = m_i).
  KOKKOS_FORCEINLINE_FUNCTION void obstacle_contact(int i, const Vec<Dim, Position>& xi,
                                                    const Vec<Dim, Real>& vi, int si, Real ri,
                                                    Vec<Dim, Real>& force,
                                                    SpinValue& torque) const {
    Real dn;
    Vec<Dim, Real> n;
    if (!obstacle.touches(xi, ri, dn, n)) {
      if constexpr (V::friction)
        for (int d = 0; d < Dim; ++d) p.obstacle_spring(i, d) = 0;
      return;
    }
    const auto& c = table.obstacle(si);
    const auto normal = clamped_normal<Model>(c, dn, dot(vi, n), table.normal_force_floor);
    force += normal.force * n;
    if constexpr (V::friction) {
      const Vec<Dim, Real> vc = contact_point_velocity(vi, n, ri * load_spin<Dim>(p.omega, i));
      Vec<Dim, Real> xi_t;
      for (int d = 0; d < Dim; ++d) xi_t[d] = p.obstacle_spring(i, d);
      const Vec<Dim, Real> ft = friction(c, normal, n, vc, xi_t);
      for (int d = 0; d < Dim; ++d) p.obstacle_spring(i, d) = xi_t[d];
      force += ft;
      torque += contact_torque(ri, n, ft);
    }
  }

  // Contacts with a slab's walls (models/z_walls.hpp): normal forces only, along z. Not
  // part of the contact virial, which sums pair forces.
  KOKKOS_FORCEINLINE_FUNCTION void wall_contacts(int i, const Vec<Dim, Position>& xi,
                                                 const Vec<Dim, Real>& vi,
                                                 Vec<Dim, Real>& force) const {
    const int si = p.species(i);
    const Real ri = table.radius(si);
    for (int side = 0; side < 2; ++side) {
      Real dn, nz;
      if (!walls.touches(side, xi[Dim - 1], ri, dn, nz)) continue;
      const auto normal =
          clamped_normal<Model>(table.wall(si), dn, vi[Dim - 1] * nz, table.normal_force_floor);
      force[Dim - 1] += normal.force * nz;
    }
  }

  KOKKOS_FORCEINLINE_FUNCTION int find_slot(int i, int partner) const {
    for (int s = 0; s < Store::history_slots; ++s)
      if (p.history_partner(i, s) == partner) return s;
    return -1;
  }

  // The slot that holds the contact with `partner`, or a fresh zeroed one.
  KOKKOS_FORCEINLINE_FUNCTION int claim_slot(int i, int partner, int& used) const {
    int free_slot = -1;
    for (int s = 0; s < Store::history_slots; ++s) {
      const int owner = p.history_partner(i, s);
      if (owner == partner) {
        used |= 1 << s;
        return s;
      }
      if (owner < 0 && free_slot < 0) free_slot = s;
    }
    if (free_slot < 0) {
      history_overflow() = 1;
      return -1;
    }
    p.history_partner(i, free_slot) = partner;
    for (int d = 0; d < Dim; ++d) p.history_spring(i, Dim * free_slot + d) = 0;
    used |= 1 << free_slot;
    return free_slot;
  }

  // Contacts that ended this step lose their history (docs/contact_model.md: the spring
  // is reset at separation).
  KOKKOS_FORCEINLINE_FUNCTION void release_unused_slots(int i, int used) const {
    for (int s = 0; s < Store::history_slots; ++s) {
      if (used & (1 << s)) continue;
      p.history_partner(i, s) = -1;
      for (int d = 0; d < Dim; ++d) p.history_spring(i, Dim * s + d) = 0;
    }
  }
};

}  // namespace granshock

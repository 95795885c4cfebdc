// The force kernel: for each particle, the sum of its Hertz contacts with the
// neighbours in the Verlet list and, when the scene has one, with the obstacle.
// Friction and obstacle are template parameters: a frictionless scene compiles no
// tangential force, history or torque; a scene without obstacle no wall contact.
#pragma once

#include <Kokkos_Core.hpp>

#include "box_geometry.hpp"
#include "contact_history.hpp"
#include "hertz_contact.hpp"
#include "particle_store.hpp"
#include "species_table.hpp"
#include "vec.hpp"

namespace granshock {

template <int Dim, class Real>
struct CylinderGeometry {
  Vec<Dim, Real> centre;  // the axis is along z; in 3-D centre[2] is ignored
  Real radius;
};

// Mode: forces (the time step) or virial (field sampling: per particle
// W_i = sum_j 1/2 r_ij (x) F_ij, with r_ij = x_i - x_j, written to `virial`; forces, torques
// and contact history are left untouched, so sampling cannot change the trajectory).
enum class ForceMode { forces, virial };

template <class Traits, class ExecSpace, ForceMode Mode = ForceMode::forces>
struct ContactForceKernel {
  static constexpr int Dim = Traits::dim;
  using Real = typename Traits::real;
  using Mem = typename ExecSpace::memory_space;
  using History = ContactHistory<Dim, Real, Mem>;

  ParticleStore<Dim, Real, Mem> p;
  Kokkos::View<int*, Mem> offsets, neighbours;
  SpeciesTable<Real, Mem> table;
  BoxGeometry<Dim, Real> box;
  CylinderGeometry<Dim, Real> cylinder;
  History history;
  Real dt;
  Kokkos::View<Real * [Traits::dim * Traits::dim], Mem> virial;  // ForceMode::virial only

  KOKKOS_INLINE_FUNCTION Vec<Dim, Real> load(
      const typename ParticleStore<Dim, Real, Mem>::VectorView& a, int i) const {
    Vec<Dim, Real> r;
    for (int d = 0; d < Dim; ++d) r[d] = a(i, d);
    return r;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const Vec<Dim, Real> xi = load(p.x, i);
    const Vec<Dim, Real> vi = load(p.v, i);
    const int si = p.species(i);
    const Real ri = table.radius(si);
    Vec<Dim, Real> force = Vec<Dim, Real>::zero();
    Real torque = 0;
    Real w[Dim * Dim] = {};
    int used_slots = 0;  // bit s set when slot s carried a contact this step

    for (int k = offsets(i); k < offsets(i + 1); ++k) {
      const int j = neighbours(k);
      const int sj = p.species(j);
      const Real rsum = ri + table.radius(sj);
      const Vec<Dim, Real> dx = box.minimum_image(xi - load(p.x, j));
      const Real r2 = dot(dx, dx);
      if (r2 >= rsum * rsum) continue;
      const Real r = dmath::sqrt(r2);
      const Vec<Dim, Real> n = (Real(1) / r) * dx;
      const Vec<Dim, Real> vrel = vi - load(p.v, j);
      const HertzCoefficients<Real>& c = table.pair(si, sj);
      const NormalContact<Real> normal = hertz_normal(c, rsum - r, dot(vrel, n));
      Vec<Dim, Real> pair_force = normal.force * n;
      if constexpr (Traits::friction) {
        const int slot =
            Mode == ForceMode::forces ? claim_slot(i, p.id(j), used_slots) : find_slot(i, p.id(j));
        const Vec<2, Real> vc =
            contact_point_velocity(vrel, n, ri * p.omega(i) + table.radius(sj) * p.omega(j));
        Vec<2, Real> xi_t = Vec<2, Real>::zero();
        if (slot >= 0) xi_t = {{history.spring(i, 2 * slot), history.spring(i, 2 * slot + 1)}};
        const Vec<2, Real> ft = hertz_tangential(c, normal, n, vc, dt, xi_t);
        if constexpr (Mode == ForceMode::forces) {
          if (slot >= 0) {
            history.spring(i, 2 * slot) = xi_t[0];
            history.spring(i, 2 * slot + 1) = xi_t[1];
          }
          torque += contact_torque(ri, n, ft);
        }
        pair_force += ft;
      }
      force += pair_force;
      if constexpr (Mode == ForceMode::virial)
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) w[a * Dim + b] += Real(0.5) * dx[a] * pair_force[b];
    }
    if constexpr (Mode == ForceMode::virial) {
      for (int k = 0; k < Dim * Dim; ++k) virial(i, k) = w[k];
      return;
    } else {
      if constexpr (Traits::friction) release_unused_slots(i, used_slots);
      if constexpr (Traits::obstacle) obstacle_contact(i, xi, vi, si, ri, force, torque);
      for (int d = 0; d < Dim; ++d) p.f(i, d) = force[d];
      if constexpr (Traits::friction) p.torque(i) = torque;
    }
  }

  KOKKOS_INLINE_FUNCTION int find_slot(int i, int partner) const {
    for (int s = 0; s < History::slots; ++s)
      if (history.partner(i, s) == partner) return s;
    return -1;
  }

  // Contact with the fixed cylinder: overlap r_i + R - |x_i - x_c|, radial normal,
  // wall coefficients (R* = r_i, m* = m_i).
  KOKKOS_INLINE_FUNCTION void obstacle_contact(int i, const Vec<Dim, Real>& xi,
                                               const Vec<Dim, Real>& vi, int si, Real ri,
                                               Vec<Dim, Real>& force, Real& torque) const {
    Vec<Dim, Real> dx = xi - cylinder.centre;
    if constexpr (Dim == 3) dx[2] = 0;
    const Real r2 = dot(dx, dx);
    const Real reach = ri + cylinder.radius;
    if (r2 >= reach * reach) {
      if constexpr (Traits::friction) history.wall_spring(i, 0) = history.wall_spring(i, 1) = 0;
      return;
    }
    const Real r = dmath::sqrt(r2);
    const Vec<Dim, Real> n = (Real(1) / r) * dx;
    const HertzCoefficients<Real>& c = table.wall(si);
    const NormalContact<Real> normal = hertz_normal(c, reach - r, dot(vi, n));
    force += normal.force * n;
    if constexpr (Traits::friction) {
      const Vec<2, Real> vc = contact_point_velocity(vi, n, ri * p.omega(i));
      Vec<2, Real> xi_t{{history.wall_spring(i, 0), history.wall_spring(i, 1)}};
      const Vec<2, Real> ft = hertz_tangential(c, normal, n, vc, dt, xi_t);
      history.wall_spring(i, 0) = xi_t[0];
      history.wall_spring(i, 1) = xi_t[1];
      force += ft;
      torque += contact_torque(ri, n, ft);
    }
  }

  // The slot that holds the contact with `partner`, or a fresh zeroed one.
  KOKKOS_INLINE_FUNCTION int claim_slot(int i, int partner, int& used) const {
    int free_slot = -1;
    for (int s = 0; s < History::slots; ++s) {
      const int owner = history.partner(i, s);
      if (owner == partner) {
        used |= 1 << s;
        return s;
      }
      if (owner < 0 && free_slot < 0) free_slot = s;
    }
    if (free_slot < 0) {
      history.overflow() = 1;
      return -1;
    }
    history.partner(i, free_slot) = partner;
    for (int d = 0; d < Dim; ++d) history.spring(i, Dim * free_slot + d) = 0;
    used |= 1 << free_slot;
    return free_slot;
  }

  // Contacts that ended this step lose their history (DESIGN.md 2.1: reset at separation).
  KOKKOS_INLINE_FUNCTION void release_unused_slots(int i, int used) const {
    for (int s = 0; s < History::slots; ++s) {
      if (used & (1 << s)) continue;
      history.partner(i, s) = -1;
      for (int d = 0; d < Dim; ++d) history.spring(i, Dim * s + d) = 0;
    }
  }
};

}  // namespace granshock

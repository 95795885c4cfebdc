// The LIGGGHTS `hertz` contact law for one contact (DESIGN.md section 2.1), shared by
// particle-particle and particle-obstacle contacts.
#pragma once

#include <Kokkos_Core.hpp>

#include "device_math.hpp"
#include "pair_properties.hpp"
#include "vec.hpp"

namespace granshock {

// Normal force magnitude along n (n points from the partner to this particle):
//   Fn = kn dn - gn vn,  kn = kn_coef sqrt(dn),  gn = gn_coef dn^(1/4),
// with vn = (v_i - v_j) . n (< 0 approaching). Without limit_force the floor is -max,
// so the damping may pull at the end of a contact as in LIGGGHTS.
template <class Real>
struct NormalContact {
  Real force;    // signed magnitude along n
  Real sqrt_dn;  // reused by the tangential force
};

template <class Real>
KOKKOS_INLINE_FUNCTION NormalContact<Real> hertz_normal(const HertzCoefficients<Real>& c, Real dn,
                                                        Real vn) {
  const Real sqrt_dn = dmath::sqrt(dn);
  const Real kn = c.kn_coef * sqrt_dn;
  const Real gn = c.gn_coef * dmath::sqrt(sqrt_dn);
  return {dmath::max(kn * dn - gn * vn, c.normal_force_floor), sqrt_dn};
}

// Tangential force with history in 2-D. The spring xi accumulates the tangential slip
// vt dt and is rotated into the current tangent plane (keeping its length). As in
// LIGGGHTS' tangential history model, the spring force is held at the Coulomb limit,
// |kt xi| <= mu |Fn| (xi is shortened when it would exceed it), and the total
// Ft = -kt xi - gt vt is capped at mu |Fn| as well (DESIGN.md 2.1).
// Capping the spring itself matters for Hertz contacts: resetting xi to absorb the
// damping term instead (xi = -(Ft + gt vt)/kt) stores a large spring of the wrong
// sign, which kt ~ dn^(1/2) outgrows gt ~ dn^(1/4) while the overlap grows; the force
// then briefly pushes along the slip, and a sliding impact transmits only ~0.9 mu Fn
// (found by tests/physics/test_friction_impact.cpp).
// vc is the relative velocity of the contact points; returns Ft and updates xi.
template <class Real>
KOKKOS_INLINE_FUNCTION Vec<2, Real> hertz_tangential(const HertzCoefficients<Real>& c,
                                                     const NormalContact<Real>& normal,
                                                     const Vec<2, Real>& n, const Vec<2, Real>& vc,
                                                     Real dt, Vec<2, Real>& xi) {
  const Vec<2, Real> vt = vc - dot(vc, n) * n;
  // Rotate the stored spring into the tangent plane, preserving its magnitude.
  const Real old_len2 = dot(xi, xi);
  xi = xi - dot(xi, n) * n;
  const Real new_len2 = dot(xi, xi);
  if (new_len2 > Real(0)) xi = dmath::sqrt(old_len2 / new_len2) * xi;
  xi += dt * vt;

  const Real kt = c.kt_coef * normal.sqrt_dn;
  const Real gt = c.gt_coef * dmath::sqrt(normal.sqrt_dn);
  const Real limit = c.friction * (normal.force > Real(0) ? normal.force : -normal.force);
  const Real spring = kt * dmath::sqrt(dot(xi, xi));
  if (spring > limit) xi = (limit / spring) * xi;  // spring > limit >= 0, so spring > 0

  Vec<2, Real> ft = Real(-1) * (kt * xi + gt * vt);
  const Real ft_len = dmath::sqrt(dot(ft, ft));
  if (ft_len > limit) ft = (limit / ft_len) * ft;
  return ft;
}

// Velocity of this particle's contact point relative to the partner's, in 2-D, for
// spins about z: v_rel - (r_i w_i + r_j w_j) (z x n), with z x n = (-n_y, n_x).
template <class Real>
KOKKOS_INLINE_FUNCTION Vec<2, Real> contact_point_velocity(const Vec<2, Real>& vrel,
                                                           const Vec<2, Real>& n, Real spin_sum) {
  Vec<2, Real> vc;
  vc[0] = vrel[0] + spin_sum * n[1];
  vc[1] = vrel[1] - spin_sum * n[0];
  return vc;
}

// z-torque on this particle from a force ft applied at its contact point -r_i n.
template <class Real>
KOKKOS_INLINE_FUNCTION Real contact_torque(Real radius, const Vec<2, Real>& n,
                                           const Vec<2, Real>& ft) {
  return -radius * (n[0] * ft[1] - n[1] * ft[0]);
}

}  // namespace granshock

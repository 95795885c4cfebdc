// The tangential force with history shared by every contact law (docs/contact_model.md,
// "Friction"): Ft = -kt xi - gt vt, capped at mu |Fn| (Coulomb), where the spring xi
// accumulates the tangential slip vt dt, is rotated into the current tangent plane
// (keeping its length) and reset at separation. kt and gt come from the law
// (Model::tangential). As in LIGGGHTS' tangential history model, the spring force is
// held at the Coulomb limit, |kt xi| <= mu |Fn| (xi is shortened when it would exceed it).
// Capping the spring itself matters for Hertz contacts: resetting xi to absorb the
// damping term instead (xi = -(Ft + gt vt)/kt) stores a large spring of the wrong sign,
// which kt ~ dn^(1/2) outgrows gt ~ dn^(1/4) while the overlap grows; the force then
// briefly pushes along the slip, and a sliding impact transmits only ~0.9 mu Fn (found by
// tests/physics/test_friction_impact.cpp). The same in 2-D and 3-D: in 2-D the spins are
// about z (scalars), in 3-D vectors (device/spin.hpp).
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/device_math.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

// vc is the relative velocity of the contact points, n the unit normal towards this
// particle, `normal_force` the signed normal force; returns Ft and updates xi.
template <int Dim, class Real>
KOKKOS_FORCEINLINE_FUNCTION Vec<Dim, Real> tangential_force(Real kt, Real gt, Real friction,
                                                            Real normal_force,
                                                            const Vec<Dim, Real>& n,
                                                            const Vec<Dim, Real>& vc, Real dt,
                                                            Vec<Dim, Real>& xi) {
  const Vec<Dim, Real> vt = vc - dot(vc, n) * n;
  // Rotate the stored spring into the tangent plane, preserving its magnitude.
  const Real old_len2 = dot(xi, xi);
  xi = xi - dot(xi, n) * n;
  const Real new_len2 = dot(xi, xi);
  if (new_len2 > Real(0)) xi = dmath::sqrt(old_len2 / new_len2) * xi;
  xi += dt * vt;

  const Real limit = friction * (normal_force > Real(0) ? normal_force : -normal_force);
  const Real spring = kt * dmath::sqrt(dot(xi, xi));
  if (spring > limit) xi = (limit / spring) * xi;  // spring > limit >= 0, so spring > 0

  Vec<Dim, Real> ft = Real(-1) * (kt * xi + gt * vt);
  const Real ft_len = dmath::sqrt(dot(ft, ft));
  if (ft_len > limit) ft = (limit / ft_len) * ft;
  return ft;
}

// Velocity of this particle's contact point relative to the partner's:
// v_rel - (r_i w_i + r_j w_j) x n, `spin_sum` being r_i w_i + r_j w_j (the contact points
// lie at -r_i n from i and +r_j n from j). In 2-D the spins are about z, z x n = (-n_y, n_x).
template <class Real>
KOKKOS_FORCEINLINE_FUNCTION Vec<2, Real> contact_point_velocity(const Vec<2, Real>& vrel,
                                                                const Vec<2, Real>& n,
                                                                Real spin_sum) {
  Vec<2, Real> vc;
  vc[0] = vrel[0] + spin_sum * n[1];
  vc[1] = vrel[1] - spin_sum * n[0];
  return vc;
}

template <class Real>
KOKKOS_FORCEINLINE_FUNCTION Vec<3, Real> contact_point_velocity(const Vec<3, Real>& vrel,
                                                                const Vec<3, Real>& n,
                                                                const Vec<3, Real>& spin_sum) {
  return vrel - cross(spin_sum, n);
}

// The torque on this particle from a force ft applied at its contact point -r_i n:
// -r_i n x ft, its z-component in 2-D.
template <class Real>
KOKKOS_FORCEINLINE_FUNCTION Real contact_torque(Real radius, const Vec<2, Real>& n,
                                                const Vec<2, Real>& ft) {
  return -radius * (n[0] * ft[1] - n[1] * ft[0]);
}

template <class Real>
KOKKOS_FORCEINLINE_FUNCTION Vec<3, Real> contact_torque(Real radius, const Vec<3, Real>& n,
                                                        const Vec<3, Real>& ft) {
  return -radius * cross(n, ft);
}

}  // namespace granshock

// The normal force of a contact as the solver applies it (docs/contact_model.md,
// "limit_force"): the law's own force (kernels/models/contact_law.hpp), clamped at a floor
// of 0 with contact.limit_force (no attraction at the end of a contact) and left as it is
// otherwise. Applied here, once for every law, by the force kernel
// (kernels/solver/contact_forces.hpp) and the restitution calibration, so that a new law
// cannot forget it.
#pragma once

#include <Kokkos_Core.hpp>
#include <limits>

#include "core/contact_settings.hpp"
#include "kernels/device/device_math.hpp"

namespace granshock {

// The floor of the normal force: 0 with limit_force, -max otherwise (no clamp).
template <class Real>
Real normal_force_floor(const ContactOptions& o) {
  return o.limit_force ? Real(0) : -std::numeric_limits<Real>::max();
}

template <class Law, class Real>
KOKKOS_FORCEINLINE_FUNCTION typename Law::template Normal<Real> clamped_normal(
    const typename Law::template Coefficients<Real>& c, Real dn, Real vn, Real floor) {
  auto normal = Law::normal(c, dn, vn);
  normal.force = dmath::max(normal.force, floor);
  return normal;
}

}  // namespace granshock

// The linear spring-dashpot contact (docs/contact_model.md, "Linear spring-dashpot"): a
// constant normal stiffness kn, kt = kn, and the damping that restores e exactly,
//   gn = sqrt(4 m* kn / (1 + (pi / ln e)^2)) = -2 beta sqrt(m* kn),  gt = gn,
//   Fn = kn dn - gn vn.
// For a linear oscillator the closed forms hold at every impact speed: the contact lasts
// t_c = pi / omega_d with omega_d = sqrt(kn/m* - (gn / 2m*)^2), and the rebound speed is
// exactly e times the impact speed (tests/physics/test_hooke_contact.cpp). The dashpot
// force jumps to gn |vn| when a contact starts; with the half-step velocity the dashpot
// sees, that makes velocity Verlet first order in dt for this law (e off by 0.7 % at
// dt = t_c/100 for e = 0.5).
//
// The laws of this family differ only in how kn is chosen, `Stiffness::of(pair, options)`
// on the host: hooke.hpp from a characteristic impact speed, linear.hpp as given.
#pragma once

#include <Kokkos_Core.hpp>
#include <cmath>

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "kernels/device/device_math.hpp"

namespace granshock {

template <class Stiffness>
struct SpringDashpot {
  template <class Real>
  struct Coefficients {
    Real kn, gn, kt, gt;
    Real friction;
  };
  template <class Real>
  struct Normal {
    Real force;  // signed magnitude along n (n points from the partner to this particle)
  };
  template <class Real>
  struct Spring {
    Real kt, gt;
  };

  static double stiffness(const PairProperties& p, const ContactOptions& o) {
    return Stiffness::of(p, o);
  }
  static double damping(const PairProperties& p, const ContactOptions& o) {
    return -2.0 * p.beta * std::sqrt(p.mass_star * stiffness(p, o));
  }

  template <class Real>
  static Coefficients<Real> coefficients(const PairProperties& p, const ContactOptions& o) {
    Coefficients<Real> c;
    c.kn = c.kt = Real(stiffness(p, o));
    c.gn = c.gt = Real(damping(p, o));
    c.friction = Real(p.friction);
    return c;
  }

  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION static Normal<Real> normal(const Coefficients<Real>& c, Real dn,
                                                         Real vn) {
    return {c.kn * dn - c.gn * vn};
  }

  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION static Spring<Real> tangential(const Coefficients<Real>& c,
                                                             const Normal<Real>&) {
    return {c.kt, c.gt};
  }

  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION static double elastic_energy(const Coefficients<Real>& c, double dn) {
    return 0.5 * double(c.kn) * dn * dn;
  }

  // The damped half period pi / omega_d (the contact's duration at any speed).
  static double collision_time(const PairProperties& p, const ContactOptions& o, double) {
    const double kn = stiffness(p, o), gn = damping(p, o);
    const double decay = gn / (2.0 * p.mass_star);
    return M_PI / std::sqrt(kn / p.mass_star - decay * decay);
  }
  // The undamped bound v sqrt(m*/kn).
  static double peak_overlap(const PairProperties& p, const ContactOptions& o, double v) {
    return v * std::sqrt(p.mass_star / stiffness(p, o));
  }
  static double peak_normal_stiffness(const PairProperties& p, const ContactOptions& o, double) {
    return stiffness(p, o);
  }
  static double peak_tangential_stiffness(const PairProperties& p, const ContactOptions& o,
                                          double) {
    return stiffness(p, o);
  }
  // gn / (2 sqrt(m* kn)) = -beta (beta <= 0 from e; a calibrated beta may be > 0).
  static double damping_ratio(const PairProperties& p) { return -p.beta; }
};

}  // namespace granshock

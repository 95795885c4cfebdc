// The LIGGGHTS `hertz` contact law (docs/design.md, "Contact models"; docs/contact_model.md):
//   Fn = kn dn - gn vn,   kn = 4/3 Y* sqrt(R* dn),  gn = -2 sqrt(5/6) beta sqrt(Sn m*),
//   Sn = 2 Y* sqrt(R* dn),  kt = St = 8 G* sqrt(R* dn),  gt = -2 sqrt(5/6) beta sqrt(St m*),
// with vn = (v_i - v_j) . n (< 0 approaching) and beta = ln e / sqrt(ln^2 e + pi^2). The
// damping is tuned to the Hertz spring, so the continuous law restores exactly e at every
// impact speed. One contact costs two square roots: the per-pair constants are arranged
// so that kn = kn_coef sqrt(dn), gn = gn_coef dn^(1/4), kt = kt_coef sqrt(dn),
// gt = gt_coef dn^(1/4). Elastic energy 8/15 Y* sqrt(R*) dn^(5/2).
#pragma once

#include <Kokkos_Core.hpp>
#include <cmath>

#include "core/contact_settings.hpp"
#include "core/pair_properties.hpp"
#include "core/variant_names.hpp"
#include "kernels/device/device_math.hpp"
#include "models/law_key.hpp"

namespace granshock {

struct HertzModel {
  static constexpr const char* name = choice_name(ContactModelKind::hertz);
  static constexpr ContactModelKind kind = ContactModelKind::hertz;
  using Parameters = NoLawParameters;  // everything from the materials

  template <class Real>
  struct Coefficients {
    Real kn_coef, gn_coef, kt_coef, gt_coef;
    Real friction;
    Real energy_coef;
  };
  template <class Real>
  struct Normal {
    Real force;    // signed magnitude along n (n points from the partner to this particle)
    Real sqrt_dn;  // reused by the tangential spring
  };
  template <class Real>
  struct Spring {
    Real kt, gt;
  };

  template <class Real>
  static Coefficients<Real> coefficients(const PairProperties& p, const ContactOptions&) {
    const double sqrt_r = std::sqrt(p.radius_star);
    const double damping = -2.0 * std::sqrt(5.0 / 6.0) * p.beta;
    Coefficients<Real> c;
    c.kn_coef = Real(4.0 / 3.0 * p.youngs_star * sqrt_r);
    c.gn_coef = Real(damping * std::sqrt(2.0 * p.youngs_star * sqrt_r * p.mass_star));
    c.kt_coef = Real(8.0 * p.shear_star * sqrt_r);
    c.gt_coef = Real(damping * std::sqrt(8.0 * p.shear_star * sqrt_r * p.mass_star));
    c.friction = Real(p.friction);
    c.energy_coef = Real(8.0 / 15.0 * p.youngs_star * sqrt_r);
    return c;
  }

  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION static Normal<Real> normal(const Coefficients<Real>& c, Real dn,
                                                         Real vn) {
    const Real sqrt_dn = dmath::sqrt(dn);
    const Real kn = c.kn_coef * sqrt_dn;
    const Real gn = c.gn_coef * dmath::sqrt(sqrt_dn);
    return {kn * dn - gn * vn, sqrt_dn};
  }

  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION static Spring<Real> tangential(const Coefficients<Real>& c,
                                                             const Normal<Real>& normal) {
    return {c.kt_coef * normal.sqrt_dn, c.gt_coef * dmath::sqrt(normal.sqrt_dn)};
  }

  // Elastic energy of one contact at overlap dn, J.
  template <class Real>
  KOKKOS_FORCEINLINE_FUNCTION static double elastic_energy(const Coefficients<Real>& c, double dn) {
    return double(c.energy_coef) * dn * dn * dmath::sqrt(dn);
  }

  // t_c = 2.87 (m*^2 / (R* Y*^2 v))^(1/5): duration of an elastic impact at relative
  // normal speed v (Johnson, Contact Mechanics, 1985, eq. 11.24).
  static double collision_time(const PairProperties& p, const ContactOptions&, double v) {
    return 2.87 *
           std::pow(p.mass_star * p.mass_star / (p.radius_star * p.youngs_star * p.youngs_star * v),
                    0.2);
  }
  // delta_max = (15 m* v^2 / (16 Y* sqrt(R*)))^(2/5) (Johnson 1985, eq. 11.23).
  static double peak_overlap(const PairProperties& p, const ContactOptions&, double v) {
    return std::pow(15.0 * p.mass_star * v * v / (16.0 * p.youngs_star * std::sqrt(p.radius_star)),
                    0.4);
  }
  // Normal and tangential stiffness at the peak overlap of an impact at speed v: the
  // linearised law the stability limit of velocity Verlet is taken from.
  static double peak_normal_stiffness(const PairProperties& p, const ContactOptions& o, double v) {
    return 2.0 * p.youngs_star * std::sqrt(p.radius_star) * std::sqrt(peak_overlap(p, o, v));
  }
  static double peak_tangential_stiffness(const PairProperties& p, const ContactOptions& o,
                                          double v) {
    return 8.0 * p.shear_star * std::sqrt(p.radius_star) * std::sqrt(peak_overlap(p, o, v));
  }
  // Damping ratio of the linearised law: -sqrt(5/6) beta.
  static double damping_ratio(const PairProperties& p) { return -std::sqrt(5.0 / 6.0) * p.beta; }
};

}  // namespace granshock

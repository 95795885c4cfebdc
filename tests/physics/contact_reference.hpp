// Independent references for the head-on contact tests (test_head_on_collision.cpp,
// test_hooke_contact.cpp): the effective constants of the `granshock collide` pairs,
// computed here from the paper's material data, and a classical RK4 integration of the
// overlap under a contact law written in the test, so that a reference shares nothing with
// the solver but the formulas (docs/contact_model.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

namespace granshock::test {

// Y*, R*, m* of a `granshock collide` pair: d = 1 mm spheres of steel (E 210 GPa, nu 0.303,
// rho 7850 kg/m3) and aluminium (E 69 GPa, nu 0.33, rho 7850/2.907 kg/m3), the obstacle an
// aluminium wall of infinite mass and radius.
struct PairReference {
  double youngs_star, radius_star, mass_star;
};

inline PairReference reference_for(const std::string& pair) {
  const double d = 1e-3, r = 0.5e-3;
  const double m_steel = 7850.0 * M_PI * d * d * d / 6.0;
  const double m_al = m_steel / 2.907;
  const double inv_y_steel = (1 - 0.303 * 0.303) / 210e9;
  const double inv_y_al = (1 - 0.33 * 0.33) / 69e9;
  if (pair == "steel-steel") return {1 / (2 * inv_y_steel), r / 2, m_steel / 2};
  if (pair == "steel-aluminium")
    return {1 / (inv_y_steel + inv_y_al), r / 2, m_steel * m_al / (m_steel + m_al)};
  if (pair == "aluminium-aluminium") return {1 / (2 * inv_y_al), r / 2, m_al / 2};
  if (pair == "steel-obstacle") return {1 / (inv_y_steel + inv_y_al), r, m_steel};  // Al cylinder
  return {1 / (2 * inv_y_al), r, m_al};  // aluminium-obstacle
}

// beta = ln e / sqrt(ln^2 e + pi^2), the damping parameter of both laws.
inline double reference_beta(double e) {
  const double l = std::log(e);
  return l / std::sqrt(l * l + M_PI * M_PI);
}

// Hertz's peak overlap of an elastic impact at speed v,
// (15 m* v^2 / (16 Y* sqrt(R*)))^(2/5) (Johnson, Contact Mechanics, 1985, eq. 11.23).
inline double hertz_peak_overlap(const PairReference& p, double v) {
  return std::pow(15.0 * p.mass_star * v * v / (16.0 * p.youngs_star * std::sqrt(p.radius_star)),
                  0.4);
}

struct ContactOutcome {
  double restitution, duration, peak_overlap;
};

// Integrates x'' = accel(x, x') for the overlap x from x(0) = 0, x'(0) = v with classical
// RK4 at step h until x returns to 0; the end is interpolated linearly between the steps.
template <class Accel>
ContactOutcome integrate_overlap(const Accel& accel, double v, double h) {
  double x = 0, xd = v, t = 0, peak = 0;
  while (true) {
    const double k1x = xd, k1v = accel(x, xd);
    const double k2x = xd + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, xd + 0.5 * h * k1v);
    const double k3x = xd + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, xd + 0.5 * h * k2v);
    const double k4x = xd + h * k3v, k4v = accel(x + h * k3x, xd + h * k3v);
    const double x_new = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v_new = xd + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x_new <= 0 && t > 0) {
      return {-v_new / v, t + h * x / (x - x_new), peak};  // interpolate the zero crossing
    }
    x = x_new;
    xd = v_new;
    peak = std::max(peak, x);
    t += h;
  }
}

}  // namespace granshock::test

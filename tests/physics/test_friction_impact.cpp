// docs/contact_model.md: an oblique impact of a steel sphere on the fixed
// aluminium cylinder with Coulomb friction mu = 0.3 (limit_force on, so Fn >= 0 and the
// Coulomb bound mu |Fn| integrates to mu times the normal impulse).
//  - Sliding regime (v_t/v_n = 4, above the gross-slip threshold
//    mu (1 + e_eff)(1 + m r^2 / I) = 0.3 * 1.55 * 3.5 = 1.63 for a solid sphere):
//    tangential impulse = mu x normal impulse (Coulomb's law), within 0.5 %.
//  - Sticking regime (v_t/v_n = 0.2): the tangential impulse stays below mu x normal
//    impulse and matches an independent RK4 integration of the same tangential law
//    (spring with history, damping, Coulomb cap) written here, within 2 %.
//  - Both: the cumulative tangential impulse never exceeds mu x the cumulative normal
//    impulse, and the spin-up obeys I dw = r J_t.
// The set-up and the solver run are in oblique_impact.hpp (shared with the hooke test).
#include <gtest/gtest.h>

#include <cmath>

#include "core/solver.hpp"
#include "physics/oblique_impact.hpp"

using namespace granshock;
using namespace granshock::test;

namespace {

// Independent reference: RK4 on the overlap x and the contact-point slip velocity u
// of a sphere on a flat wall,
//   m x'' = -Fn,  Fn = max(0, 4/3 Y* sqrt(R*) x^(3/2) + gn x'),
//   u' = -(1/m + r^2/I) Ft,  xi' = u,  spring -kt xi held at |kt xi| <= mu Fn,
//   Ft = -kt xi - gt u capped at mu Fn, with kt = 8 G* sqrt(R* x) and gn, gt from beta
//   (docs/design.md, "Contact models"; the spring cap as in LIGGGHTS' tangential history model).
double reference_tangential_impulse(double vn, double vt) {
  const double m = 7850.0 * M_PI * kD * kD * kD / 6.0;
  const double inv_y = (1 - 0.303 * 0.303) / 210e9 + (1 - 0.33 * 0.33) / 69e9;
  const double inv_g = 2 * (2 - 0.303) * (1 + 0.303) / 210e9 + 2 * (2 - 0.33) * (1 + 0.33) / 69e9;
  const double Y = 1 / inv_y, G = 1 / inv_g, R = kR;
  const double beta = std::log(kE) / std::sqrt(std::log(kE) * std::log(kE) + M_PI * M_PI);
  const double damp = -2 * std::sqrt(5.0 / 6.0) * beta;
  const double inv_mt = 1 / m + kR * kR / (0.4 * m * kR * kR);  // 1/m + r^2/I = 3.5/m
  struct State {
    double x, xd, u, xi;
  };
  auto forces = [&](const State& s, double& fn, double& ft) {
    fn = ft = 0;
    if (s.x <= 0) return;
    const double sq = std::sqrt(R * s.x);
    fn = std::max(0.0, 4.0 / 3.0 * Y * sq * s.x + damp * std::sqrt(2 * Y * sq * m) * s.xd);
    const double kt = 8 * G * sq, gt = damp * std::sqrt(8 * G * sq * m);
    double spring = -kt * s.xi;
    if (std::abs(spring) > kMu * fn) spring = std::copysign(kMu * fn, spring);
    ft = spring - gt * s.u;
    if (std::abs(ft) > kMu * fn) ft = std::copysign(kMu * fn, ft);
  };
  auto deriv = [&](const State& s) {
    double fn, ft;
    forces(s, fn, ft);
    return State{s.xd, -fn / m, inv_mt * ft, s.u};
  };
  const double tc = 2.87 * std::pow(m * m / (R * Y * Y * vn), 0.2);
  const double h = tc / 20000;
  State s{0, vn, vt, 0};
  double jt = 0;
  for (int k = 0; k < 200000 && !(s.x <= 0 && k > 0); ++k) {
    const State k1 = deriv(s);
    auto add = [](const State& a, const State& b, double f) {
      return State{a.x + f * b.x, a.xd + f * b.xd, a.u + f * b.u, a.xi + f * b.xi};
    };
    const State k2 = deriv(add(s, k1, h / 2)), k3 = deriv(add(s, k2, h / 2)),
                k4 = deriv(add(s, k3, h));
    State next{s.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
               s.xd + h / 6 * (k1.xd + 2 * k2.xd + 2 * k3.xd + k4.xd),
               s.u + h / 6 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u),
               s.xi + h / 6 * (k1.xi + 2 * k2.xi + 2 * k3.xi + k4.xi)};
    // Hold the spring at the Coulomb limit, as the law prescribes.
    double fn, ft;
    forces(next, fn, ft);
    if (next.x > 0) {
      const double kt = 8 * G * std::sqrt(R * next.x);
      if (kt * std::abs(next.xi) > kMu * fn) next.xi = std::copysign(kMu * fn / kt, next.xi);
    }
    // Tangential impulse from the change of the sphere's centre velocity: m dv_t = Ft dt,
    // and u changes by inv_mt Ft dt, so dJ = du / inv_mt.
    jt += -(next.u - s.u) / inv_mt;
    s = next;
  }
  return jt;
}

}  // namespace

TEST(FrictionImpact, SlidingTangentialImpulseIsMuTimesNormal) {
  const Impact r = simulate_oblique_impact(ContactModelKind::hertz, 1.0, 4.0);
  ASSERT_GT(r.jn, 0);
  EXPECT_NEAR(r.jt / r.jn, kMu, 0.005 * kMu);
  EXPECT_LT(r.worst_coulomb_excess, 1e-9);
  // I dw = r J_t: the torque of the tangential force at the contact point -r n.
  const Species sp{"steel", steel(), kD};
  EXPECT_NEAR(sp.moment_of_inertia() * r.spin, -kR * r.jt, 1e-3 * kR * r.jt);
}

TEST(FrictionImpact, StickingStaysBelowTheCoulombLimit) {
  const Impact r = simulate_oblique_impact(ContactModelKind::hertz, 1.0, 0.2);
  const double ref = reference_tangential_impulse(1.0, 0.2);
  ASSERT_GT(r.jn, 0);
  EXPECT_LT(r.jt / r.jn, 0.9 * kMu) << "a sticking impact must not reach gross sliding";
  EXPECT_LT(r.worst_coulomb_excess, 1e-9);
  EXPECT_NEAR(r.jt, ref, 0.02 * std::abs(ref)) << "reference tangential impulse " << ref;
  const Species sp{"steel", steel(), kD};
  EXPECT_NEAR(sp.moment_of_inertia() * r.spin, -kR * r.jt, 1e-3 * std::abs(kR * r.jt));
}

// Test 1 of the foundation issue: head-on impacts through the solver's kernels
// (`granshock collide`) against an independent, high-accuracy integration of the same
// contact law written here (classical RK4 with 20 000 steps per contact, not the
// solver's force function). Effective restitution within 0.5 % of e, contact duration
// within 2 % of the reference, at dt = t_c/100.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "head_on_collision.hpp"

using namespace granshock;

namespace {

// The pair's effective constants, computed here from the paper's material data
// (docs/design.md, "Contact models") so that the reference shares nothing with the solver but the
// formulas.
struct Reference {
  double youngs_star, radius_star, mass_star;
};

Reference reference_for(const std::string& pair) {
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

struct ContactOutcome {
  double restitution, duration;
};

// Integrates m* x'' = -F(x, x') for the overlap x with x(0) = 0, x'(0) = v, where
// F = 4/3 Y* sqrt(R*) x^(3/2) + 2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(R* x) m*) x'
// (the hertz law of docs/design.md, "Contact models" written for the overlap), until x returns to
// 0.
ContactOutcome integrate_contact(const Reference& p, double e, double v, bool limit_force) {
  const double beta = std::log(e) / std::sqrt(std::log(e) * std::log(e) + M_PI * M_PI);
  const auto accel = [&](double x, double xdot) {
    if (x <= 0) return 0.0;
    const double stiffness = 4.0 / 3.0 * p.youngs_star * std::sqrt(p.radius_star * x);
    const double damping =
        -2.0 * std::sqrt(5.0 / 6.0) * beta *
        std::sqrt(2.0 * p.youngs_star * std::sqrt(p.radius_star * x) * p.mass_star);
    double force = stiffness * x + damping * xdot;
    if (limit_force && force < 0) force = 0;
    return -force / p.mass_star;
  };
  const double tc = 2.87 * std::pow(p.mass_star * p.mass_star /
                                        (p.radius_star * p.youngs_star * p.youngs_star * v),
                                    0.2);
  const double h = tc / 20000.0;
  double x = 0, xd = v, t = 0;
  while (true) {
    const double k1x = xd, k1v = accel(x, xd);
    const double k2x = xd + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, xd + 0.5 * h * k1v);
    const double k3x = xd + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, xd + 0.5 * h * k2v);
    const double k4x = xd + h * k3v, k4v = accel(x + h * k3x, xd + h * k3v);
    const double x_new = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v_new = xd + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x_new <= 0 && t > 0) {
      return {-v_new / v, t + h * x / (x - x_new)};  // interpolate the zero crossing
    }
    x = x_new;
    xd = v_new;
    t += h;
  }
}

using Case = std::tuple<std::string, double, double>;  // pair, speed (m/s), e

class HeadOnCollision : public ::testing::TestWithParam<Case> {};

TEST_P(HeadOnCollision, MatchesTheContactLaw) {
  const auto& [pair, speed, e] = GetParam();
  CollisionOptions o;
  o.pair = pair;
  o.speed_m_per_s = speed;
  o.restitution = e;  // dt defaults to t_c / 100
  const CollisionResult r = run_head_on_collision(o);
  const ContactOutcome ref = integrate_contact(reference_for(pair), e, speed, false);

  std::printf("[ measured ] %-20s v=%4.1f e=%.1f  e_eff=%.5f (%+.3f %%)  t_contact err %+.3f %%\n",
              pair.c_str(), speed, e, r.e_eff, 100 * (r.e_eff / e - 1),
              100 * (r.t_contact / ref.duration - 1));
  EXPECT_NEAR(r.dt / r.t_c, 0.01, 1e-12);
  // The continuous model restores e exactly (the reference gives e to 1e-6).
  EXPECT_NEAR(ref.restitution, e, 1e-5 * e);
  EXPECT_NEAR(r.e_eff, e, 0.005 * e) << "effective restitution off by more than 0.5 %";
  EXPECT_NEAR(r.t_contact, ref.duration, 0.02 * ref.duration) << "contact duration off by > 2 %";
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = std::get<0>(info.param);
  for (char& c : name)
    if (c == '-') c = '_';
  const int speed_cm = int(std::lround(std::get<1>(info.param) * 100));
  const int e_pct = int(std::lround(std::get<2>(info.param) * 100));
  return name + "_v" + std::to_string(speed_cm) + "cm_e" + std::to_string(e_pct);
}

INSTANTIATE_TEST_SUITE_P(
    PaperPairs, HeadOnCollision,
    ::testing::Combine(::testing::Values("steel-steel", "steel-aluminium", "aluminium-aluminium",
                                         "steel-obstacle", "aluminium-obstacle"),
                       ::testing::Values(0.1, 1.0, 5.0), ::testing::Values(0.5, 0.9)),
    case_name);

// With limit_force the attractive end of the contact is cut off: the effective
// restitution rises (0.550 for e = 0.5 in the reference), and the solver follows the
// reference within the same 0.5 %.
TEST(HeadOnCollisionLimitForce, RaisesRestitutionAsTheReferenceDoes) {
  for (const double e : {0.5, 0.9}) {
    CollisionOptions o;
    o.pair = "steel-aluminium";
    o.speed_m_per_s = 1.0;
    o.restitution = e;
    o.limit_force = true;
    const CollisionResult r = run_head_on_collision(o);
    const ContactOutcome ref = integrate_contact(reference_for(o.pair), e, 1.0, true);
    EXPECT_GT(ref.restitution, e * 1.001);
    EXPECT_NEAR(r.e_eff, ref.restitution, 0.005 * ref.restitution);
    EXPECT_NEAR(r.t_contact, ref.duration, 0.02 * ref.duration);
  }
}

// Single precision through the same kernels: the overlap (~1e-6 m) is resolved against
// positions of ~1e-3 m with 24-bit mantissas, so a looser 2 % on e is the price; this
// test records that price rather than hiding it.
TEST(HeadOnCollisionSinglePrecision, RestitutionWithinTwoPercent) {
  CollisionOptions o;
  o.pair = "steel-steel";
  o.speed_m_per_s = 1.0;
  o.precision = Precision::single_precision;
  const CollisionResult r = run_head_on_collision(o);
  EXPECT_NEAR(r.e_eff, 0.5, 0.02 * 0.5);
}

}  // namespace

// docs/contact_model.md: head-on impacts through the solver's kernels
// (`granshock collide`) against an independent, high-accuracy integration of the same
// contact law written here (classical RK4 with 20 000 steps per contact, not the
// solver's force function). Effective restitution within 0.5 % of e, contact duration
// within 2 % of the reference, at dt = t_c/100.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "cases/collision/head_on_collision.hpp"
#include "cases/gas/homogeneous_gas.hpp"
#include "physics/contact_reference.hpp"

using namespace granshock;
using namespace granshock::test;

namespace {

// Integrates m* x'' = -F(x, x') for the overlap x with x(0) = 0, x'(0) = v, where
// F = 4/3 Y* sqrt(R*) x^(3/2) + 2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(R* x) m*) x'
// (the hertz law of docs/contact_model.md written for the overlap), until x returns to 0.
ContactOutcome integrate_contact(const PairReference& p, double e, double v, bool limit_force) {
  const double beta = reference_beta(e);
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
  return integrate_overlap(accel, v, tc / 20000.0);
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

// Single precision through the same kernels: positions are double and the separation
// (~1e-3 m) is rounded to float only after it is formed, so the overlap (~1e-6 m) errs by
// about 1e-4 of itself and e_eff meets the double test's 0.5 % (it took 2 % when
// positions were float; far from the origin: test_single_precision.cpp).
TEST(HeadOnCollisionSinglePrecision, RestitutionWithinHalfAPercent) {
  CollisionOptions o;
  o.pair = "steel-steel";
  o.speed_m_per_s = 1.0;
  o.precision = Precision::single_precision;
  const CollisionResult r = run_head_on_collision(o);
  EXPECT_NEAR(r.e_eff, 0.5, 0.005 * 0.5);
}

}  // namespace

// docs/contact_model.md: contact.softening divides every Young's modulus. Hertz theory (Johnson,
// Contact Mechanics, eq. 11.24) makes the collision time and the peak overlap grow as
// softening^(2/5) and keeps the restitution: measured through the solver's kernels at
// dt = t_c/100 of each setting, for a particle pair and a particle against the (fallback
// aluminium) cylinder, against the theory to 1 % (the contact time's interpolation between
// steps) and e_eff to 0.002.
TEST(Softening, CollisionTimeAndOverlapGrowAsTheoryRestitutionIsKept) {
  const SolverSetup hard = paper_mixture(0.5);
  SolverSetup soft = hard;
  soft.contacts.softening = 1000;
  const double growth = std::pow(1000.0, 0.4);  // 15.85
  for (const int b : {0, 1, -1}) {
    const CollisionResult h = collide_species(hard, 0, b, 1.0, 0, false, 1.0);
    const CollisionResult s = collide_species(soft, 0, b, 1.0, 0, false, 1.0);
    std::printf("[ measured ] %-16s t_c x %.4f, overlap x %.4f, e_eff %.5f -> %.5f\n",
                h.pair.c_str(), s.t_contact / h.t_contact, s.max_overlap / h.max_overlap, h.e_eff,
                s.e_eff);
    EXPECT_NEAR(s.t_c / h.t_c, growth, 1e-9 * growth);  // the guard's formula
    EXPECT_NEAR(s.t_contact / h.t_contact, growth, 0.01 * growth);
    EXPECT_NEAR(s.max_overlap / h.max_overlap, growth, 0.01 * growth);
    EXPECT_NEAR(s.e_eff, h.e_eff, 0.002);
    EXPECT_NEAR(s.e_eff, 0.5, 0.005 * 0.5);
  }
}

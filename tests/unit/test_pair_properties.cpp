// Effective pair properties and collision times against hand calculations from the
// formulas of docs/design.md, "Contact models" with the paper's materials (numbers computed
// separately, to 6+ significant digits; tolerances are relative 1e-9 unless stated).
#include <gtest/gtest.h>

#include <cmath>

#include "core/pair_properties.hpp"
#include "kernels/models/clamped_normal.hpp"
#include "kernels/models/hertz.hpp"
#include "kernels/models/models.hpp"
#include "kernels/models/time_step_guard.hpp"

using namespace granshock;

namespace {
const Species kSteel{"steel", steel(), 1e-3};
const Species kAluminium{"aluminium", aluminium(), 1e-3};
void expect_rel(double value, double reference, double tol = 1e-9) {
  EXPECT_NEAR(value / reference, 1.0, tol) << value << " vs " << reference;
}
}  // namespace

TEST(PairProperties, MassesOfThePapersSpheres) {
  // m = rho pi d^3 / 6: steel 7850 kg/m3, aluminium 7850/2.907 kg/m3, d = 1 mm.
  expect_rel(kSteel.mass_kg(), 4.110250388446646e-06);
  expect_rel(kAluminium.mass_kg(), 1.413914822307068e-06);
}

TEST(PairProperties, SteelSteel) {
  const PairProperties p = particle_pair(kSteel, kSteel, 0.5, 0.0);
  expect_rel(p.youngs_star, 115614446740.82875);  // E / (2 (1 - nu^2))
  expect_rel(p.shear_star, 23742860747.895596);   // E / (4 (2 - nu)(1 + nu))
  expect_rel(p.radius_star, 0.25e-3);
  expect_rel(p.mass_star, 0.5 * 4.110250388446646e-06);
  expect_rel(p.beta, -0.2154537619662468);  // ln 0.5 / sqrt(ln^2 0.5 + pi^2)
}

TEST(PairProperties, SteelAluminium) {
  const PairProperties p = particle_pair(kSteel, kAluminium, 0.5, 0.0);
  expect_rel(p.youngs_star, 58007292417.39122);
  expect_rel(p.shear_star, 11704301764.175594);
  expect_rel(p.mass_star, 1.0520221111969916e-06);
}

TEST(PairProperties, WallHasInfiniteMassAndRadius) {
  const PairProperties p = particle_obstacle(kAluminium, aluminium(), 0.5, 0.0);
  expect_rel(p.radius_star, 0.5e-3);  // R* = r_i
  expect_rel(p.mass_star, kAluminium.mass_kg());
  expect_rel(p.youngs_star, 38716193468.7465);
}

TEST(PairProperties, RestitutionOneMeansNoDamping) {
  EXPECT_EQ(damping_beta(1.0), 0.0);
  const auto c =
      HertzModel::coefficients<double>(particle_pair(kSteel, kSteel, 1.0, 0.0), ContactOptions{});
  EXPECT_EQ(c.gn_coef, 0.0);
  EXPECT_EQ(c.gt_coef, 0.0);
}

// The clamp is the solver's, once for every law (models/clamped_normal.hpp): at the end of
// a damped contact (overlap small, the pair parting fast) every law's own force pulls,
// and limit_force clamps it at 0; without it the force stays as the law gives it.
TEST(PairProperties, LimitForceClampsEveryLaw) {
  const PairProperties p = particle_pair(kSteel, kSteel, 0.5, 0.0);
  ContactOptions limited;
  limited.limit_force = true;
  EXPECT_EQ(normal_force_floor<double>(limited), 0.0);
  EXPECT_LT(normal_force_floor<double>(ContactOptions{}), -1e300);
  int laws = 0;
  for_each_contact_law([&](auto law) {
    using Law = decltype(law);
    ++laws;
    ContactOptions o;  // each law's keys: a speed of 1 m/s, a stiffness of 1e6 N/m
    with_law_parameters(Law::kind, [&](auto parameters) {
      for (std::size_t k = 0; k < parameters.keys.size(); ++k)
        o.law_parameters[k] =
            parameters.keys[k].fallback == LawKey::Default::inflow_speed ? 1.0 : 1e6;
    });
    const auto c = Law::template coefficients<double>(p, o);
    const double dn = 1e-9, vn = 5.0;  // barely touching, parting at 5 m/s
    const double own = Law::normal(c, dn, vn).force;
    EXPECT_LT(own, 0) << Law::name;
    EXPECT_EQ(clamped_normal<Law>(c, dn, vn, normal_force_floor<double>(limited)).force, 0.0)
        << Law::name;
    EXPECT_EQ(clamped_normal<Law>(c, dn, vn, normal_force_floor<double>(ContactOptions{})).force,
              own)
        << Law::name;
  });
  EXPECT_EQ(laws, int(std::size(Choices<ContactModelKind>::table)));
}

TEST(CollisionTime, HertzFormula) {
  // t_c = 2.87 (m*^2 / (R* Y*^2 v))^(1/5), steel-steel at 1 m/s and aluminium-obstacle.
  expect_rel(
      HertzModel::collision_time(particle_pair(kSteel, kSteel, 0.5, 0), ContactOptions{}, 1.0),
      3.0076297101757045e-06);
  expect_rel(HertzModel::collision_time(particle_obstacle(kAluminium, aluminium(), 0.5, 0),
                                        ContactOptions{}, 1.0),
             3.492208251901344e-06);  // Y* = 3.8716e10 Pa, m* = 1.4139e-6 kg, R* = 0.5 mm
  // t_c ~ v^(-1/5)
  const PairProperties p = particle_pair(kSteel, kAluminium, 0.5, 0);
  expect_rel(HertzModel::collision_time(p, ContactOptions{}, 32.0),
             HertzModel::collision_time(p, ContactOptions{}, 1.0) / 2.0, 1e-12);
}

// docs/stability.md: the time-step guard warns past t_c/10, refuses a dt
// past the stable limit with a message naming t_c and a safe dt, and --force overrides.
#include <gtest/gtest.h>

#include <cmath>

#include "cases/collision/head_on_collision.hpp"
#include "core/user_error.hpp"
#include "kernels/models/hertz.hpp"
#include "kernels/models/hooke.hpp"
#include "kernels/models/time_step_guard.hpp"

using namespace granshock;

namespace {
const Species kSteel{"steel", steel(), 1e-3};
PairProperties steel_pair(double e = 0.5) {
  return particle_pair(kSteel, kSteel, e, 0.0);
}
}  // namespace

TEST(TimeStepGuard, VerdictsAcrossTheRange) {
  const double tc = HertzModel::collision_time(steel_pair(), ContactOptions{}, 1.0);
  using V = TimeStepAssessment::Verdict;
  EXPECT_EQ(assess_time_step({steel_pair()}, ContactModelKind::hertz, ContactOptions{}, 1.0,
                             tc / 100, false)
                .verdict,
            V::ok);
  EXPECT_EQ(assess_time_step({steel_pair()}, ContactModelKind::hertz, ContactOptions{}, 1.0, tc / 5,
                             false)
                .verdict,
            V::warn);
  const auto refused =
      assess_time_step({steel_pair()}, ContactModelKind::hertz, ContactOptions{}, 1.0, tc, false);
  EXPECT_EQ(refused.verdict, V::refuse);
  EXPECT_NE(refused.message.find("stable limit"), std::string::npos) << refused.message;
  EXPECT_NE(refused.message.find("t_c"), std::string::npos) << refused.message;
  EXPECT_NE(refused.message.find("--force"), std::string::npos) << refused.message;
  EXPECT_EQ(
      assess_time_step({steel_pair()}, ContactModelKind::hertz, ContactOptions{}, 1.0, 0.0, false)
          .verdict,
      V::refuse);
  EXPECT_EQ(
      assess_time_step({steel_pair()}, ContactModelKind::hertz, ContactOptions{}, 1.0, -1e-7, false)
          .verdict,
      V::refuse);
}

TEST(TimeStepGuard, StiffestPairAndFastestSpeedDecide) {
  const Species al{"aluminium", aluminium(), 1e-3};
  const auto a = assess_time_step({particle_pair(al, al, 0.5, 0), steel_pair()},
                                  ContactModelKind::hertz, ContactOptions{}, 2.0, 1e-8, false);
  EXPECT_EQ(a.stiffest_pair, "steel-steel");
  EXPECT_DOUBLE_EQ(a.t_c, HertzModel::collision_time(steel_pair(), ContactOptions{}, 2.0));
  // A faster impact is stiffer: the stable step shrinks with speed as v^(-1/5).
  EXPECT_LT(stable_time_step(ContactModelKind::hertz, steel_pair(), ContactOptions{}, 10.0, false),
            stable_time_step(ContactModelKind::hertz, steel_pair(), ContactOptions{}, 1.0, false));
  // Friction's tangential spring with the rolling mass 2/7 m* is the stiffer mode.
  EXPECT_LT(stable_time_step(ContactModelKind::hertz, steel_pair(), ContactOptions{}, 1.0, true),
            stable_time_step(ContactModelKind::hertz, steel_pair(), ContactOptions{}, 1.0, false));
}

TEST(TimeStepGuard, StableLimitIsBelowTheContactTime) {
  // The linearised peak stiffness bounds the step well below t_c: 0.305 t_c for e = 0.5
  // (omega_max t_c = 4.03, margin sqrt(2 + z^2) - z = 1.231 with z = 0.197).
  const double ratio =
      stable_time_step(ContactModelKind::hertz, steel_pair(), ContactOptions{}, 1.0, false) /
      HertzModel::collision_time(steel_pair(), ContactOptions{}, 1.0);
  EXPECT_GT(ratio, 0.29);
  EXPECT_LT(ratio, 0.32);
}

TEST(TimeStepGuard, HookeLimitDependsOnTheCharacteristicVelocityOnly) {
  // kn is fixed by V, so neither t_c nor the stable step depends on the impact speed, and
  // omega0 dt_stable = sqrt(2 + beta^2) - |beta| (zeta = |beta| for hooke).
  ContactOptions o;
  HookeParameters::set_characteristic_velocity(o, 2.0);
  const PairProperties p = steel_pair();
  const double dt = stable_time_step(ContactModelKind::hooke, p, o, 1.0, false);
  EXPECT_DOUBLE_EQ(dt, stable_time_step(ContactModelKind::hooke, p, o, 30.0, false));
  EXPECT_DOUBLE_EQ(collision_time(ContactModelKind::hooke, p, o, 1.0),
                   collision_time(ContactModelKind::hooke, p, o, 30.0));
  const double omega0 = std::sqrt(HookeModel::stiffness(p, o) / p.mass_star);
  const double b = std::abs(p.beta);
  EXPECT_NEAR(omega0 * dt, std::sqrt(2.0 + b * b) - b, 1e-12);
  // A stiffer law at a larger V: kn ~ V^(2/5), so dt_stable ~ V^(-1/5).
  ContactOptions fast = o;
  HookeParameters::set_characteristic_velocity(fast, 64.0);
  EXPECT_NEAR(stable_time_step(ContactModelKind::hooke, p, fast, 1.0, false), dt / 2.0, 1e-12 * dt);
}

TEST(TimeStepGuard, CollideRefusesAnUnstableStepUnlessForced) {
  CollisionOptions o;
  o.pair = "steel-steel";
  o.speed_m_per_s = 1.0;
  o.dt = 2e-6;  // t_c = 3.0e-6 s, stable limit 0.92e-6 s at 1 m/s
  try {
    run_head_on_collision(o);
    FAIL() << "dt past the stable limit was accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("past the stable limit"), std::string::npos) << e.what();
  }
  o.force = true;
  const CollisionResult r = run_head_on_collision(o);
  EXPECT_EQ(r.time_step.verdict, TimeStepAssessment::Verdict::refuse);
}

TEST(TimeStepGuard, CollideRejectsBadArguments) {
  CollisionOptions o;
  o.pair = "steel-copper";
  EXPECT_THROW(run_head_on_collision(o), UserError);
  o.pair = "steel-steel";
  o.speed_m_per_s = 0;
  EXPECT_THROW(run_head_on_collision(o), UserError);
  o.speed_m_per_s = 1;
  o.restitution = 1.5;
  EXPECT_THROW(run_head_on_collision(o), UserError);
  o.restitution = 0;
  EXPECT_THROW(run_head_on_collision(o), UserError);
}

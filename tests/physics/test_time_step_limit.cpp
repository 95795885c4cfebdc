// The time-step guard (kernels/models/time_step_guard.cpp, generic over the contact laws
// through peak_normal_stiffness and damping_ratio) against what the solver does: a
// head-on impact (`granshock collide`, forced past the guard) stays bounded while its
// e_eff is finite and below 1.5. The measured limit is the largest bounded dt below the
// first unbounded one: dt/t_c is scanned upwards from 0.1 in steps of 0.01 (e_eff is not
// monotonic in dt: whether rounding starts the contact just before or just after a step
// flips it near the limit) and the bracket around the first failure is bisected.
// The guard's refusal threshold must be at or below the measured limit, and not needlessly
// early: at least 0.7 of it.
//
// This caught the guard's previous limit, the stability limit of a sustained damped
// oscillation, omega dt < 2 (sqrt(1 + zeta^2) - zeta): about sqrt(2) too large for an
// impact, which a step can resolve in a single force evaluation. There e_eff reached 2.9
// (hooke, e = 0.9), 2.3 (hooke, e = 0.5) and 2.1 (hertz, e = 0.9) at dt the guard accepted; the
// guard now uses omega dt <= sqrt(2 + zeta^2) - zeta (kernels/models/time_step_guard.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "cases/collision/head_on_collision.hpp"
#include "core/user_error.hpp"
#include "core/variant_names.hpp"
#include "models/law_parameters.hpp"
#include "physics/contact_reference.hpp"

using namespace granshock;
using namespace granshock::test;

namespace {

constexpr double kBounded = 1.5;  // e_eff at or above this is an unbounded impact

double forced_e_eff(CollisionOptions o, double dt) {
  o.dt = dt;
  o.force = true;
  try {
    return run_head_on_collision(o).e_eff;
  } catch (const UserError&) {  // passed through, or never parted
    return std::numeric_limits<double>::infinity();
  }
}

bool bounded(double e_eff) {
  return std::isfinite(e_eff) && e_eff < kBounded;
}

using Case = std::tuple<ContactModelKind, std::string, double>;  // law, pair, e

class TimeStepLimit : public ::testing::TestWithParam<Case> {};

TEST_P(TimeStepLimit, GuardRefusesAtOrBelowTheMeasuredLimit) {
  const auto& [model, pair, e] = GetParam();
  CollisionOptions o;
  o.pair = pair;
  o.speed_m_per_s = 1.0;
  o.restitution = e;
  o.model = model;  // hooke: characteristic velocity = the impact speed
  // A law's required parameters (linear's stiffness) in the middle of their ranges, on a
  // log scale: kn = 3.2e4 N/m, a contact of 25 us for 1 mm steel.
  with_law_parameters(model, [&](auto parameters) {
    for (const LawKey& k : parameters.keys)
      if (k.fallback == LawKey::Default::required)
        o.law_parameters[k.name] = std::sqrt(k.lo * k.hi);
  });
  const CollisionResult nominal = run_head_on_collision(o);
  const double t_c = nominal.t_c, guard = nominal.time_step.dt_stable;

  double good = 0.1 * t_c, bad = 0;
  ASSERT_TRUE(bounded(forced_e_eff(o, good)));
  for (int k = 11; k <= 200 && bad == 0; ++k) {
    const double dt = 0.01 * k * t_c;
    if (bounded(forced_e_eff(o, dt)))
      good = dt;
    else
      bad = dt;
  }
  ASSERT_GT(bad, 0) << "no unbounded impact up to dt = 2 t_c";
  for (int k = 0; k < 20; ++k) {
    const double mid = 0.5 * (good + bad);
    if (bounded(forced_e_eff(o, mid)))
      good = mid;
    else
      bad = mid;
  }
  const double measured = good;

  // The previous limit, for the record.
  const double beta = std::abs(reference_beta(e));
  const double zeta = model == ContactModelKind::hertz ? std::sqrt(5.0 / 6.0) * beta : beta;
  const double previous =
      guard * 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta) / (std::sqrt(2.0 + zeta * zeta) - zeta);
  std::printf(
      "[ measured ] %-5s %-18s e=%.1f: guard refuses past dt = %.4g t_c, bounded up to "
      "%.4g t_c (guard / measured %.3f); e_eff at the guard's limit %.3f, at the previous "
      "limit %.4g t_c %.3f\n",
      to_string(model).c_str(), pair.c_str(), e, guard / t_c, measured / t_c, guard / measured,
      forced_e_eff(o, guard), previous / t_c, forced_e_eff(o, previous));
  EXPECT_LE(guard, measured);
  EXPECT_GE(guard, 0.7 * measured);

  // At its limit the guard accepts the step (no --force) and the impact is bounded; just
  // past it, it refuses.
  o.dt = guard;
  const CollisionResult at_limit = run_head_on_collision(o);
  EXPECT_NE(at_limit.time_step.verdict, TimeStepAssessment::Verdict::refuse);
  EXPECT_TRUE(bounded(at_limit.e_eff)) << at_limit.e_eff;
  o.dt = 1.001 * guard;
  EXPECT_THROW(run_head_on_collision(o), UserError);
}

std::string case_name(const ::testing::TestParamInfo<Case>& param) {
  std::string pair = std::get<1>(param.param);
  for (char& c : pair)
    if (c == '-') c = '_';
  return to_string(std::get<0>(param.param)) + "_" + pair + "_e" +
         std::to_string(int(std::lround(std::get<2>(param.param) * 100)));
}

// Every law of core/variant_names.hpp (which models.hpp ties to ContactLaws).
std::vector<ContactModelKind> every_law() {
  std::vector<ContactModelKind> laws;
  for (const auto& c : Choices<ContactModelKind>::table) laws.push_back(c.value);
  return laws;
}

INSTANTIATE_TEST_SUITE_P(Laws, TimeStepLimit,
                         ::testing::Combine(::testing::ValuesIn(every_law()),
                                            ::testing::Values("steel-steel", "aluminium-obstacle"),
                                            ::testing::Values(0.5, 0.9)),
                         case_name);

}  // namespace

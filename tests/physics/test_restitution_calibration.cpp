// contact.restitution_mode = "discrete" (docs/contact_model.md, "Restitution at the chosen
// time step"): the damping calibrated by the reduced integrator of
// kernels/models/restitution_calibration.cpp, checked through the solver's own kernels
// (`granshock collide`). At dt = t_c/5, about the paper's step, the restitution averaged
// over the phase of the first contact step must be within 0.2 % of e for every pair and the
// paper's three inflow speeds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "cases/collision/head_on_collision.hpp"
#include "core/pair_properties.hpp"
#include "core/user_error.hpp"
#include "kernels/models/restitution_calibration.hpp"
#include "kernels/models/time_step_guard.hpp"
#include "models/hooke_parameters.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;

namespace {

CollisionOptions impact(const std::string& pair, double speed, double e) {
  CollisionOptions o;
  o.pair = pair;
  o.speed_m_per_s = speed;
  o.restitution = e;
  return o;
}

// The collision time of the pair at this speed, from a default (t_c/100) collision.
double collision_time_of(const CollisionOptions& o) {
  CollisionOptions probe = o;
  probe.dt.reset();
  probe.restitution_mode = RestitutionMode::continuous;
  return run_head_on_collision(probe).t_c;
}

struct PhaseAverage {
  double solver = 0;            // mean e_eff of the solver's collisions over the phases
  double worst_mismatch = 0;    // largest |solver - reduced integrator| over the phases
  double reported_average = 0;  // the calibration's own phase average
};

// The pair of `o` with the paper's materials, as the reduced integrator needs it.
PairProperties paper_pair(const CollisionOptions& o) {
  SolverSetup paper;
  paper.species = {{"steel", steel(), 1e-3}, {"aluminium", aluminium(), 1e-3}};
  paper.contacts = ContactSettings::uniform(2, o.restitution, 0.0);
  paper.obstacle = make_obstacle(ObstacleShape::cylinder, {0, 0, 0}, {1e-2}, aluminium());
  const auto dash = o.pair.find('-');
  const int i = o.pair.substr(0, dash) == "steel" ? 0 : 1;
  const std::string second = o.pair.substr(dash + 1);
  return second == "obstacle" ? paper.obstacle_pair(i) : paper.pair(i, second == "steel" ? 0 : 1);
}

// Runs the solver at every calibration phase with the mode and dt of `o`.
PhaseAverage over_phases(CollisionOptions o) {
  PhaseAverage a;
  ContactOptions options;
  HookeParameters::set_characteristic_velocity(options, o.speed_m_per_s);
  PairProperties props = paper_pair(o);
  for (int k = 0; k < kCalibrationPhases; ++k) {
    o.phase = (k + 0.5) / kCalibrationPhases;
    const CollisionResult r = run_head_on_collision(o);
    a.solver += r.e_eff / kCalibrationPhases;
    if (r.calibration) a.reported_average = r.calibration->e_eff;
    // The same impact in the reduced integrator, with the damping the solver ran with.
    props.beta = r.beta;
    const double reduced =
        discrete_restitution(o.model, props, options, r.dt, o.speed_m_per_s, o.phase);
    a.worst_mismatch = std::max(a.worst_mismatch, std::abs(reduced - r.e_eff));
  }
  return a;
}

using Case = std::tuple<std::string, double>;  // pair, speed (m/s)

class DiscreteRestitution : public ::testing::TestWithParam<Case> {};

TEST_P(DiscreteRestitution, PhaseAveragedSolverRestitutionWithinPointTwoPercentAtTcOver5) {
  const auto& [pair, speed] = GetParam();
  const double e = 0.5;
  CollisionOptions o = impact(pair, speed, e);
  o.dt = collision_time_of(o) / 5.0;
  const PhaseAverage continuous = over_phases(o);
  o.restitution_mode = RestitutionMode::discrete;
  const PhaseAverage discrete = over_phases(o);
  std::printf(
      "[ measured ] %-20s v=%5.3f dt=t_c/5  e_eff phase-averaged: continuous %.5f "
      "(%+.2f %%), discrete %.5f (%+.3f %%); solver vs reduced %.1e\n",
      pair.c_str(), speed, continuous.solver, 100 * (continuous.solver / e - 1), discrete.solver,
      100 * (discrete.solver / e - 1), discrete.worst_mismatch);
  EXPECT_NEAR(discrete.solver, e, 0.002 * e);
  // The reduced integrator is the solver's arithmetic up to rounding, phase by phase.
  EXPECT_LT(continuous.worst_mismatch, 1e-9);
  EXPECT_LT(discrete.worst_mismatch, 1e-9);
  EXPECT_NEAR(discrete.reported_average, e, 1e-9);
}

// The five pairs of the paper's mixture at its three inflow speeds (Table 1).
INSTANTIATE_TEST_SUITE_P(
    PaperPairsAndSpeeds, DiscreteRestitution,
    ::testing::Combine(::testing::Values("steel-steel", "steel-aluminium", "aluminium-aluminium",
                                         "steel-obstacle", "aluminium-obstacle"),
                       ::testing::Values(0.475, 1.0, 2.375)),
    [](const ::testing::TestParamInfo<Case>& c) {
      std::string name = std::get<0>(c.param) + "_" +
                         std::to_string(int(std::lround(1000 * std::get<1>(c.param))));
      for (char& ch : name)
        if (ch == '-') ch = '_';
      return name;
    });

// The bias the calibration removes is real: without it the phase-averaged restitution at
// t_c/5 misses e = 0.5 by more than 1 %, and at phase 1 (the start `collide` used before
// phases existed) by more than the 0.2 % budget the other way.
TEST(DiscreteRestitution, ContinuousDampingIsBiasedAtTcOver5) {
  CollisionOptions o = impact("steel-aluminium", 1.0, 0.5);
  o.dt = collision_time_of(o) / 5.0;
  const PhaseAverage continuous = over_phases(o);
  EXPECT_LT(continuous.solver, 0.5 * (1 - 0.01));
  o.phase = 1.0;
  EXPECT_GT(run_head_on_collision(o).e_eff, 0.5 * (1 + 0.002));
}

// Other restitutions and the linear law, through the solver: e = 0.1, 0.9 and 1 (which
// needs a damping beta > 0 when the integrator loses energy) and `hooke` at e = 0.5.
TEST(DiscreteRestitution, OtherRestitutionsAndTheLinearLaw) {
  for (double e : {0.1, 0.9, 1.0}) {
    CollisionOptions o = impact("steel-aluminium", 1.0, e);
    o.dt = collision_time_of(o) / 5.0;
    o.restitution_mode = RestitutionMode::discrete;
    const PhaseAverage a = over_phases(o);
    std::printf("[ measured ] hertz e=%.1f  discrete phase-averaged %.5f\n", e, a.solver);
    EXPECT_NEAR(a.solver, e, 0.002 * e) << "e = " << e;
  }
  CollisionOptions o = impact("steel-steel", 1.0, 0.5);
  o.model = ContactModelKind::hooke;
  o.dt = collision_time_of(o) / 5.0;
  o.restitution_mode = RestitutionMode::discrete;
  const PhaseAverage a = over_phases(o);
  std::printf("[ measured ] hooke e=0.5  discrete phase-averaged %.5f\n", a.solver);
  EXPECT_NEAR(a.solver, 0.5, 0.002 * 0.5);
  EXPECT_LT(a.worst_mismatch, 1e-9);
}

// Continuous mode leaves every pair's damping exactly as the closed form gives it, so
// runs without the key are unchanged (the bitwise reference check, tests/reference/,
// covers whole runs).
TEST(DiscreteRestitution, ContinuousModeKeepsTheClosedFormDamping) {
  SolverSetup s;
  s.species = {{"steel", steel(), 1e-3}, {"aluminium", aluminium(), 1e-3}};
  s.contacts = ContactSettings::uniform(2, 0.5, 0.0);
  s.contacts.restitution[0][1] = s.contacts.restitution[1][0] = 0.7;
  s.obstacle = make_obstacle(ObstacleShape::cylinder, {0, 0, 0}, {1e-2}, aluminium());
  s.dt = 5e-7;
  s.contacts.calibration_speed_m_per_s = 1.0;
  const RestitutionCalibration c = apply_restitution_mode(s);
  EXPECT_TRUE(c.pairs.empty());
  EXPECT_TRUE(s.contacts.calibrated_beta.empty());
  EXPECT_EQ(s.pair(0, 1).beta, damping_beta(0.7));
  EXPECT_EQ(s.obstacle_pair(1).beta, damping_beta(0.5));

  // Discrete: one beta per pair, symmetric, each pair calibrated at its own e; calling
  // again gives the same betas (a resumed run).
  s.contacts.restitution_mode = RestitutionMode::discrete;
  const RestitutionCalibration first = apply_restitution_mode(s);
  ASSERT_EQ(first.pairs.size(), 5u);  // 3 particle pairs + 2 obstacle pairs
  EXPECT_EQ(s.pair(0, 1).beta, s.pair(1, 0).beta);
  EXPECT_NE(s.pair(0, 1).beta, damping_beta(0.7));
  const double beta01 = s.pair(0, 1).beta;
  apply_restitution_mode(s);
  EXPECT_EQ(s.pair(0, 1).beta, beta01);
  for (const PairCalibration& p : first.pairs) {
    EXPECT_NEAR(p.e_eff, p.restitution, 1e-9) << p.pair;
    EXPECT_LE(p.phase_min, p.e_eff);
    EXPECT_GE(p.phase_max, p.e_eff);
    EXPECT_EQ(p.speed_residuals.size(), std::size(kResidualSpeedFactors));
  }

  // Back to continuous: the calibrated damping is gone.
  s.contacts.restitution_mode = RestitutionMode::continuous;
  apply_restitution_mode(s);
  EXPECT_EQ(s.pair(0, 1).beta, damping_beta(0.7));
}

// A calibration that no damping can satisfy, or without a speed, ends in one clear message.
// At dt = t_c/3 (past the stable limit) every damping returns a faster rebound than the
// impact (measured: e_eff 1.4 to 3.7), so e = 0.01 cannot be reached.
TEST(DiscreteRestitution, UnreachableRestitutionIsAUserError) {
  SolverSetup s;
  s.species = {{"steel", steel(), 1e-3}};
  s.contacts = ContactSettings::uniform(1, 0.01, 0.0);
  s.contacts.restitution_mode = RestitutionMode::discrete;
  s.contacts.calibration_speed_m_per_s = 1.0;
  s.dt = collision_time(ContactModelKind::hertz, s.pair(0, 0), s.contacts.options, 1.0) / 3.0;
  try {
    apply_restitution_mode(s);
    ADD_FAILURE() << "e = 0.01 at t_c/3 was calibrated";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("no damping makes the steel-steel pair return e = 0.01"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(s.contacts.calibrated_beta.empty());

  s.dt = s.dt * 3.0 / 5.0;
  s.contacts.calibration_speed_m_per_s = 0;
  EXPECT_THROW(apply_restitution_mode(s), UserError);
}

// The calibration integrates about 3,700 collisions per pair: at dt = 1e-12 s (t_c/dt of
// 3e6) `collide --restitution-mode discrete` ran for more than 12 minutes. It is refused
// before any step, naming a dt that fits the cap, both in a scene and in collide.
TEST(DiscreteRestitution, ACalibrationPastTheStepCapIsRefusedUpFront) {
  SolverSetup s;
  s.species = {{"steel", steel(), 1e-3}, {"aluminium", aluminium(), 1e-3}};
  s.contacts = ContactSettings::uniform(2, 0.5, 0.0);
  s.contacts.restitution_mode = RestitutionMode::discrete;
  s.contacts.calibration_speed_m_per_s = 1.0;
  s.dt = 1e-12;
  const std::vector<PairProperties> pairs = s.all_pairs();
  const double steps =
      calibration_steps(ContactModelKind::hertz, pairs, s.contacts.options, s.dt, 1.0);
  EXPECT_GT(steps, kMaxCalibrationSteps);
  // Per pair: 32 phases of at least 113 contacts at the calibration speed, each t_c/dt.
  const double t_c = collision_time(ContactModelKind::hertz, pairs[0], s.contacts.options, 1.0);
  EXPECT_GT(steps, 3 * 32 * 113 * t_c / s.dt);
  try {
    apply_restitution_mode(s);
    ADD_FAILURE() << "a calibration of " << steps << " steps was started";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("calibrating the damping of 3 pairs at dt = 1e-12 s"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("more than the 1e+09 allowed; use dt >= "),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(s.contacts.calibrated_beta.empty());

  CollisionOptions o = impact("steel-steel", 1.0, 0.5);
  o.restitution_mode = RestitutionMode::discrete;
  o.dt = 1e-12;
  EXPECT_THROW(run_head_on_collision(o), UserError);
  // The paper's dt (about t_c/5) is far inside the cap, for every pair of 64 species.
  EXPECT_LT(calibration_steps(ContactModelKind::hertz, std::vector<PairProperties>(2144, pairs[0]),
                              s.contacts.options, t_c / 5, 1.0),
            kMaxCalibrationSteps / 10);
}

}  // namespace

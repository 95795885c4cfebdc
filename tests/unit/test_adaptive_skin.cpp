// The adaptive Verlet skin (core/skin_model.hpp, docs/design.md "Adaptive skin"): the
// model's choice against an independent minimisation and its stationarity condition, and
// a solver that adapts its skin: thinner lists in a dense gas, lists that stay complete,
// and a run that resumes bitwise from an exported state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "brute_force_contacts.hpp"
#include "cases/gas/homogeneous_gas.hpp"
#include "core/checkpoint_checks.hpp"
#include "core/skin_model.hpp"
#include "core/solver.hpp"
#include "same_particles.hpp"

using namespace granshock;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double d = 1e-3;  // diameter (m)

SkinModel model_2d() {
  SkinModel m;
  m.dim = 2;
  m.range = d;
  m.cell = 1.3 * d;
  m.smallest = 0.05 * d;
  m.largest = 0.3 * d;
  return m;
}

// A gas of area fraction phi: partners within d + s0 of a particle, uniform density.
SkinSample gas_sample(double phi, double s0, double drift_per_step) {
  const double density = phi / (pi * 0.25 * d * d);
  return {s0, density * pi * (d + s0) * (d + s0), drift_per_step};
}

// The cost written out by hand for 2-D: l0 ((d + s)/(d + s0))^2 + (2 m + c) 2 u / s,
// m = l0 (3 cell)^2 / (pi (d + s0)^2).
double cost_by_hand(const SkinModel& m, const SkinSample& at, double s) {
  const double l0 = at.partners_per_particle, r0 = d + at.skin;
  const double candidates = l0 * 9 * m.cell * m.cell / (pi * r0 * r0);
  return l0 * (d + s) * (d + s) / (r0 * r0) +
         (2 * candidates + m.build_overhead) * 2 * at.drift_per_step / s;
}

}  // namespace

TEST(SkinModel, CostIsTheFormulaOfTheHeader) {
  const SkinModel m = model_2d();
  const SkinSample at = gas_sample(0.3, 0.2 * d, 4e-7);
  for (const double s : {0.05 * d, 0.1 * d, 0.27 * d})
    EXPECT_NEAR(m.cost(at, s), cost_by_hand(m, at, s), 1e-12 * cost_by_hand(m, at, s));
}

// Independent of the golden section: a scan of 200,001 skins.
TEST(SkinModel, BestIsTheMinimumOfAFineScan) {
  const SkinModel m = model_2d();
  for (const double phi : {0.02, 0.1, 0.3, 0.5, 0.7})
    for (const double drift : {1e-8, 1e-7, 5e-7, 3e-6}) {
      const SkinSample at = gas_sample(phi, 0.3 * d, drift);
      double scan_best = m.smallest, scan_cost = m.cost(at, m.smallest);
      for (int k = 1; k <= 200000; ++k) {
        const double s = m.smallest + (m.largest - m.smallest) * k / 200000.0;
        const double c = m.cost(at, s);
        if (c < scan_cost) scan_cost = c, scan_best = s;
      }
      const double best = m.best(at);
      EXPECT_NEAR(best, scan_best, 2e-6 * d) << "phi " << phi << ", drift " << drift;
      EXPECT_LE(m.cost(at, best), scan_cost * (1 + 1e-12));
    }
}

// Inside the range the choice is stationary: d/ds of the cost is 0, i.e.
// 2 l0 (d + s) / (d + s0)^2 = (2 m + c) 2 u / s^2.
TEST(SkinModel, InteriorChoiceIsStationary) {
  const SkinModel m = model_2d();
  const SkinSample at = gas_sample(0.5, 0.3 * d, 3e-7);
  const double s = m.best(at);
  ASSERT_GT(s, m.smallest * 1.01);
  ASSERT_LT(s, m.largest * 0.99);
  const double r0 = d + at.skin, l0 = at.partners_per_particle;
  const double candidates = l0 * 9 * m.cell * m.cell / (pi * r0 * r0);
  const double lists = 2 * l0 * (d + s) / (r0 * r0);
  const double builds = (2 * candidates + m.build_overhead) * 2 * at.drift_per_step / (s * s);
  EXPECT_NEAR(lists, builds, 1e-6 * lists);
}

TEST(SkinModel, DenserGasesGetThinnerSkinsFasterOnesThicker) {
  const SkinModel m = model_2d();
  double previous = m.largest;
  for (const double phi : {0.05, 0.1, 0.2, 0.4, 0.6}) {
    const double s = m.best(gas_sample(phi, 0.3 * d, 3e-7));
    EXPECT_LE(s, previous) << "phi " << phi;
    previous = s;
  }
  EXPECT_LT(previous, 0.2 * d);
  previous = m.smallest;
  for (const double drift : {1e-8, 1e-7, 1e-6, 1e-5}) {
    const double s = m.best(gas_sample(0.3, 0.3 * d, drift));
    EXPECT_GE(s, previous) << "drift " << drift;
    previous = s;
  }
  // Clamped: a crawling gas takes the smallest skin, a racing one the largest.
  EXPECT_EQ(m.best(gas_sample(0.5, 0.3 * d, 1e-12)), m.best(gas_sample(0.5, 0.1 * d, 1e-13)));
  EXPECT_EQ(m.best(gas_sample(0.5, 0.3 * d, 1e-12)), m.smallest);
  EXPECT_EQ(m.best(gas_sample(0.5, 0.3 * d, 1e-3)), m.largest);
  // Nothing measured yet (no drift): keep the skin, inside the range.
  EXPECT_EQ(m.best(gas_sample(0.5, 0.2 * d, 0.0)), 0.2 * d);
  EXPECT_EQ(m.best(gas_sample(0.5, 0.9 * d, 0.0)), m.largest);
}

namespace {

SolverSetup adaptive_gas(double phi, int particles, GasSpec& spec) {
  SolverSetup s = paper_mixture(0.5);
  spec.particles = particles;
  spec.area_fraction = phi;
  spec.sigma_m_per_s = 2.0;
  size_periodic_box(s, spec);
  s.dt = 2e-7;
  s.adaptive_skin = true;
  return s;
}

using test::brute_force_contacts;

using test::expect_bitwise_identical;

}  // namespace

// A dense gas thins its skin below the scene's 0.3 d, and its lists stay complete: the
// contacts found through them equal a brute-force search at every check.
TEST(AdaptiveSkin, DenseGasThinsItsSkinAndListsStayComplete) {
  GasSpec spec;
  const SolverSetup s = adaptive_gas(0.5, 900, spec);
  auto solver = make_solver(s, spec.particles);
  solver->set_particles(make_homogeneous_gas(s, spec));
  EXPECT_EQ(solver->skin(), s.skin());
  double thinnest = s.skin();
  for (int check = 0; check < 30; ++check) {
    solver->advance(250);
    thinnest = std::min(thinnest, solver->skin());
    ASSERT_EQ(solver->contact_pairs(), brute_force_contacts(s, solver->particles()))
        << "check " << check << ", skin " << solver->skin() / d << " d";
  }
  EXPECT_GT(solver->list_builds(), 5);
  EXPECT_GE(thinnest, s.smallest_adaptive_skin());
  EXPECT_LT(solver->skin(), 0.2 * d) << "a dense gas should take a thin skin";
}

// Stopping, exporting the state and continuing in a new solver gives bitwise the run that
// did not stop: the skin and the step of its last build travel with the state.
TEST(AdaptiveSkin, ResumesBitwiseFromAnExportedState) {
  GasSpec spec;
  const SolverSetup s = adaptive_gas(0.4, 600, spec);
  const HostParticles gas = make_homogeneous_gas(s, spec);
  auto straight = make_solver(s, gas.size());
  straight->set_particles(gas);
  straight->advance(3000);
  auto first = make_solver(s, gas.size());
  first->set_particles(gas);
  first->advance(1700);
  const SolverState middle = first->export_state();
  EXPECT_EQ(middle.skin, first->skin());
  EXPECT_NE(middle.skin, s.skin()) << "the test must stop after the skin changed";
  EXPECT_LT(middle.last_build_step, middle.step) << "the test must stop between builds";
  auto resumed = make_solver(s, gas.size());
  resumed->import_state(middle);
  EXPECT_EQ(resumed->skin(), first->skin());
  resumed->advance(1300);
  expect_bitwise_identical(straight->particles(), resumed->particles());
  EXPECT_EQ(resumed->skin(), straight->skin());
  EXPECT_EQ(resumed->list_builds(), straight->list_builds());
}

// A state whose skin the scene cannot have made is refused, naming the attribute.
TEST(AdaptiveSkin, StateWithAForeignSkinIsRefused) {
  GasSpec spec;
  SolverSetup s = adaptive_gas(0.4, 400, spec);
  auto adaptive = make_solver(s, spec.particles);
  adaptive->set_particles(make_homogeneous_gas(s, spec));
  SolverState state = adaptive->export_state();
  s.adaptive_skin = false;
  state.skin = 0.5 * s.skin();
  auto fixed = make_solver(s, spec.particles);
  try {
    fixed->import_state(state);
    FAIL() << "no exception";
  } catch (const InvalidCheckpoint& e) {
    EXPECT_NE(std::string(e.what()).find("/state@skin"), std::string::npos) << e.what();
  }
  s.adaptive_skin = true;
  state.skin = 0.01 * s.skin();  // below the smallest adaptive skin
  auto other = make_solver(s, spec.particles);
  EXPECT_THROW(other->import_state(state), InvalidCheckpoint);
  state.skin = 0;  // a file from before the adaptive skin: the scene's
  other->import_state(state);
  EXPECT_EQ(other->skin(), s.skin());
}

// A fast dilute gas keeps the largest skin, exactly: its run is bitwise the fixed-skin
// run (a bug fixed: the search returned a skin 1e-13 inside the bound, so the adaptive
// run's lists differed from the fixed run's at round-off).
TEST(AdaptiveSkin, SkinHeldAtTheLargestIsTheFixedSkinRun) {
  GasSpec spec;
  const SolverSetup adaptive = adaptive_gas(0.05, 500, spec);
  SolverSetup fixed = adaptive;
  fixed.adaptive_skin = false;
  const HostParticles gas = make_homogeneous_gas(adaptive, spec);
  auto a = make_solver(adaptive, gas.size()), f = make_solver(fixed, gas.size());
  a->set_particles(gas);
  f->set_particles(gas);
  a->advance(4000);
  f->advance(4000);
  EXPECT_GT(a->list_builds(), 3);
  EXPECT_EQ(a->skin(), fixed.skin());
  expect_bitwise_identical(a->particles(), f->particles());
}

// A single-precision solver stores its float skin; at the smallest bound that float lies
// below the double bound, and the state must still be accepted (a bug fixed: the range
// was checked in double, so such a checkpoint could not be resumed).
TEST(AdaptiveSkin, SinglePrecisionSkinAtTheSmallestBoundIsAccepted) {
  GasSpec spec;
  SolverSetup s = adaptive_gas(0.1, 400, spec);
  s.precision = Precision::single_precision;
  // Particles at rest on a lattice 2 d apart: no partner within d + 0.3 d, so the lists
  // of every skin are the same (empty) and the state is consistent whatever skin it says.
  HostParticles lattice;
  const int per_row = int(s.box.length(0) / (2 * d));
  for (int k = 0; k < spec.particles; ++k)
    lattice.add({(0.5 + 2 * (k % per_row)) * d, (0.5 + 2 * (k / per_row)) * d, 0}, {0, 0, 0}, k % 2,
                k);
  auto first = make_solver(s, spec.particles);
  first->set_particles(lattice);
  SolverState state = first->export_state();
  ASSERT_EQ(state.neighbours.size(), 0u);
  state.skin = double(float(s.smallest_adaptive_skin()));
  ASSERT_LT(state.skin, s.smallest_adaptive_skin()) << "the case needs a float below the bound";
  auto resumed = make_solver(s, spec.particles);
  resumed->import_state(state);
  EXPECT_EQ(resumed->skin(), state.skin);
}

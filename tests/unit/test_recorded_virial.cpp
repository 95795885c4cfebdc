// The contact virial a field sample reads (docs/fields.md, "The contact virial"): the step's
// last force pass records it, and it equals what the separate virial pass computes from the
// same positions, velocities and contact history, on the host and the device paths of the
// kernels (docs/cuda.md, "Branch points"). A sample never reads a virial that no force pass
// of its state recorded: a state without one (a checkpoint from before it) is sampled with
// the virial computed from that state; a state that went through a checkpoint file samples
// as the run that wrote it would have.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "io/checkpoint_file.hpp"
#include "scene/scene_fixtures.hpp"
#include "solver_on_paths.hpp"

using namespace granshock;

namespace {

// A dense, dissipative gas (e = 0.5: the damping force depends on the velocities), with
// friction mu or without; soft, so that a few hundred steps make many contacts.
struct Gas {
  SolverSetup setup;
  FieldSampling sampling;
  HostParticles particles;  // after the warm-up: in contact
};

Gas dense_gas(double friction) {
  Gas g;
  g.setup = paper_mixture(0.5);
  g.setup.contacts = ContactSettings::uniform(2, 0.5, friction);
  for (Species& species : g.setup.species) species.material.youngs_modulus_pa *= 1e-4;
  g.setup.dt = 2e-6;
  GasSpec spec;
  spec.particles = 1200;
  spec.area_fraction = 0.45;
  spec.sigma_m_per_s = 2.0;
  size_periodic_box(g.setup, spec);
  auto warm = make_solver(g.setup, spec.particles);
  warm->set_particles(make_homogeneous_gas(g.setup, spec));
  warm->advance(300);
  g.particles = warm->particles();
  BinLayout& grid = g.sampling.grid;
  grid.n_species = 2;
  grid.nx = 6;
  grid.dx = g.setup.box.length(0) / grid.nx;
  grid.x0 = g.setup.box.lo[0];
  grid.x_period = g.setup.box.length(0);
  grid.ny = 6;
  grid.dy = g.setup.box.length(1) / grid.ny;
  grid.blocks = 2;
  g.sampling.profile = grid;
  g.sampling.profile.x_period = 0;
  return g;
}

// The state without its recorded virial, as a checkpoint from before it holds it.
SolverState without_virial(SolverState s) {
  s.contact_virial.clear();
  return s;
}

std::vector<double> virial_sums(const std::vector<double>& sums, const FieldSampling& f) {
  const int q = f.grid.quantities();
  std::vector<double> out;
  for (std::size_t k = 0; k < sums.size(); ++k)
    if (int(k % std::size_t(q)) >= f.grid.virial_index(BinLayout::w_xx)) out.push_back(sums[k]);
  return out;
}

// Equal to round-off: the device paths add with atomics, in any order (docs/fields.md,
// "Cost of sampling").
void expect_same_sums(const std::vector<double>& a, const std::vector<double>& b,
                      const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double scale = 0;
  for (double x : b) scale = std::max(scale, std::abs(x));
  std::size_t differing = 0;
  for (std::size_t k = 0; k < a.size(); ++k) differing += std::abs(a[k] - b[k]) > 1e-12 * scale;
  EXPECT_EQ(differing, 0u) << what << ": sums that differ beyond round-off";
}

}  // namespace

// Given particles (set_particles) get their forces from one pass, which records the
// virial; a solver given the same state without it computes the virial in a separate pass.
// With the springs of the contact history zeroed both passes see the same springs (fresh
// ones), so the two samples agree, friction or not, on either paths.
TEST(RecordedVirial, EqualsTheSeparatePassAtTheSameVelocities) {
  for (const double friction : {0.0, 0.4}) {
    const Gas g = dense_gas(friction);
    for (const test::Paths paths : {test::Paths::host, test::Paths::device}) {
      const std::string what =
          std::string(test::to_string(paths)) + " paths, friction " + std::to_string(friction);
      auto recorded = test::make_solver_on_paths(g.setup, g.particles.size(), paths);
      recorded->configure_sampling(g.sampling);
      recorded->set_particles(g.particles);
      recorded->sample_fields(1);
      SolverState state = without_virial(recorded->export_state());
      ASSERT_EQ(recorded->export_state().contact_virial.size(), 4 * state.size()) << what;
      std::fill(state.history_spring.begin(), state.history_spring.end(), 0.0);
      std::fill(state.history_obstacle_spring.begin(), state.history_obstacle_spring.end(), 0.0);
      auto separate = test::make_solver_on_paths(g.setup, g.particles.size(), paths);
      separate->configure_sampling(g.sampling);
      separate->import_state(state);
      separate->sample_fields(1);
      ASSERT_GT(recorded->diagnostics().contacts, 100) << what << ": too few contacts to test";
      const std::vector<double> a = recorded->field_sums(false), b = separate->field_sums(false);
      double largest = 0;
      for (double w : virial_sums(a, g.sampling)) largest = std::max(largest, std::abs(w));
      EXPECT_GT(largest, 0) << what << ": no virial sampled";
      expect_same_sums(a, b, what + ", grid");
      expect_same_sums(recorded->field_sums(true), separate->field_sums(true), what + ", profile");
    }
  }
}

// A solver that recorded a virial, then given a state without one, samples that state's
// virial (computed from it), not the one it recorded before nor zeros; a state handed on
// with its virial (a checkpoint, a backend switch) is sampled with that virial.
TEST(RecordedVirial, ASampleNeverReadsAVirialItsStateDidNotRecord) {
  const Gas g = dense_gas(0.4);
  const SolverState later = [&] {
    auto s = make_solver(g.setup, g.particles.size());
    s->set_particles(g.particles);
    s->advance(70);
    return s->export_state();
  }();
  ASSERT_FALSE(later.contact_virial.empty());

  auto reused = make_solver(g.setup, g.particles.size());
  reused->configure_sampling(g.sampling);
  reused->set_particles(g.particles);
  reused->advance(40);  // recorded a virial of step 40
  reused->import_state(without_virial(later));
  reused->sample_fields(0);
  auto fresh = make_solver(g.setup, g.particles.size());
  fresh->configure_sampling(g.sampling);
  fresh->import_state(without_virial(later));
  fresh->sample_fields(0);
  const std::vector<double> a = reused->field_sums(false), b = fresh->field_sums(false);
  double largest = 0;
  for (double w : virial_sums(b, g.sampling)) largest = std::max(largest, std::abs(w));
  ASSERT_GT(largest, 0) << "no virial sampled";
  expect_same_sums(a, b, "after a state without a virial");
  EXPECT_TRUE(reused->export_state().contact_virial.empty())
      << "a virial that no pass of this state recorded is handed on";

  // With its virial: the sample reads the recorded one, which the separate pass (at the
  // velocities after the step, the springs after the pass) does not reproduce.
  auto handed_on = make_solver(g.setup, g.particles.size());
  handed_on->configure_sampling(g.sampling);
  handed_on->import_state(later);
  handed_on->sample_fields(0);
  EXPECT_EQ(handed_on->export_state().contact_virial, later.contact_virial);
  const std::vector<double> recorded = virial_sums(handed_on->field_sums(false), g.sampling),
                            computed = virial_sums(b, g.sampling);
  ASSERT_EQ(recorded.size(), computed.size());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < recorded.size(); ++k)
    differing += std::abs(recorded[k] - computed[k]) > 1e-9 * largest;
  EXPECT_GT(differing, 0u) << "the handed-on virial was not the one sampled";
}

// A resumed run whose new production window samples the checkpoint's own step (docs/
// scene_format.md, "Extending a run") must sample it as the uninterrupted run did: the
// checkpoint file carries the virial of the step's last force pass, and a solver given
// that state samples the same sums, bitwise on row owners (docs/fields.md, "Cost of
// sampling"), to round-off with atomics.
TEST(RecordedVirial, AStateReadFromACheckpointSamplesAsTheRunThatWroteIt) {
  const Gas g = dense_gas(0.4);
  auto straight = make_solver(g.setup, g.particles.size());
  straight->configure_sampling(g.sampling);
  straight->set_particles(g.particles);
  straight->advance(70);
  ASSERT_GT(straight->diagnostics().contacts, 100) << "too few contacts to test";
  granshock::testing::TempDir dir;
  write_checkpoint(dir.path() / "checkpoint.h5", straight->export_state(), CheckpointExtras{});
  CheckpointExtras extras;
  const SolverState state = read_checkpoint(dir.path() / "checkpoint.h5", extras);
  straight->sample_fields(1);
  auto resumed = make_solver(g.setup, g.particles.size());
  resumed->configure_sampling(g.sampling);
  resumed->import_state(state);
  resumed->sample_fields(1);
  expect_same_sums(resumed->field_sums(false), straight->field_sums(false), "grid");
  expect_same_sums(resumed->field_sums(true), straight->field_sums(true), "profile");
}

// The pass that closes a call of advance() (kernels/solver/fused_step.hpp, Closing) records
// the forces and the virial a separate force pass computes from the same state. Elastic
// and without friction the forces depend on the positions alone, so the velocities it
// reads (before the second half of the step) do not matter: a solver given the particles
// (set_particles: a new list, then one unfused force pass) must find the same forces and
// virial, to round-off (its list sums each particle's contacts in another order), on
// either paths, with the periodic images that cross the box's faces.
TEST(RecordedVirial, TheClosingPassRecordsTheForcesAndVirialOfASeparatePass) {
  Gas g = dense_gas(0.0);
  g.setup.contacts = ContactSettings::uniform(2, 1.0, 0.0);
  for (const test::Paths paths : {test::Paths::host, test::Paths::device}) {
    const std::string what = std::string(test::to_string(paths)) + " paths";
    auto stepped = test::make_solver_on_paths(g.setup, g.particles.size(), paths);
    stepped->set_particles(g.particles);
    stepped->advance(37);
    ASSERT_GT(stepped->diagnostics().contacts, 100) << what << ": too few contacts to test";
    const SolverState closed = stepped->export_state();
    auto separate = test::make_solver_on_paths(g.setup, g.particles.size(), paths);
    separate->set_particles(stepped->particles());
    const SolverState computed = separate->export_state();
    ASSERT_EQ(closed.id.size(), computed.id.size()) << what;
    std::unordered_map<int, std::size_t> at;  // computed's index of each id
    for (std::size_t k = 0; k < computed.id.size(); ++k) at[computed.id[k]] = k;
    const auto compare = [&](const std::vector<double>& a, const std::vector<double>& b, int per,
                             const std::string& name) {
      ASSERT_EQ(a.size(), closed.id.size() * std::size_t(per)) << what << ", " << name;
      ASSERT_EQ(b.size(), a.size()) << what << ", " << name;
      double largest = 0;
      for (double x : b) largest = std::max(largest, std::abs(x));
      ASSERT_GT(largest, 0) << what << ", " << name << ": all zero";
      std::size_t differing = 0;
      for (std::size_t k = 0; k < closed.id.size(); ++k)
        for (int c = 0; c < per; ++c)
          differing += std::abs(a[k * std::size_t(per) + std::size_t(c)] -
                                b[at.at(closed.id[k]) * std::size_t(per) + std::size_t(c)]) >
                       1e-12 * largest;
      EXPECT_EQ(differing, 0u) << what << ", " << name << ": values beyond round-off";
    };
    compare(closed.force, computed.force, 2, "force");
    compare(closed.contact_virial, computed.contact_virial, 4, "contact virial");
  }
}

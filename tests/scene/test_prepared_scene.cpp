// The scene a run runs is prepared once (cases/bow_shock/prepared_scene.hpp; docs/design.md,
// "The bow-shock case"): checked, its damping and sigma calibrated, checked again. The
// calibrations are compared with independent calls of the calibrations themselves, and
// `--dry-run` (check_run) must report what the run's preparation reports.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cases/bow_shock/prepared_scene.hpp"
#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "kernels/models/restitution_calibration.hpp"
#include "run_helpers.hpp"
#include "scene_fixtures.hpp"

namespace granshock {
namespace {

const std::vector<std::string> kDiscrete = {"contact.restitution_mode=discrete"};

TEST(PreparedScene, DampingIsTheCalibrationsOwn) {
  const LoadedScene loaded = parse_scene(testing::small_scene(), kDiscrete);
  ASSERT_TRUE(loaded.scene.setup.contacts.calibrated_beta.empty());
  const PreparedScene p = prepare_scene(loaded, {});
  ASSERT_TRUE(p.restitution.has_value());
  EXPECT_FALSE(p.inlet.has_value());
  Scene independent = loaded.scene;
  const RestitutionCalibration c = apply_restitution_mode(independent.setup);
  EXPECT_EQ(p.scene().setup.contacts.calibrated_beta, independent.setup.contacts.calibrated_beta);
  EXPECT_EQ(p.scene().setup.contacts.obstacle_calibrated_beta,
            independent.setup.contacts.obstacle_calibrated_beta);
  ASSERT_EQ(p.restitution->pairs.size(), c.pairs.size());
  for (std::size_t k = 0; k < c.pairs.size(); ++k)
    EXPECT_EQ(p.restitution->pairs[k].beta, c.pairs[k].beta) << c.pairs[k].pair;
  // A continuous scene is left as loaded.
  const LoadedScene continuous = parse_scene(testing::small_scene());
  const PreparedScene q = prepare_scene(continuous, {});
  EXPECT_FALSE(q.restitution.has_value());
  EXPECT_TRUE(q.scene().setup.contacts.calibrated_beta.empty());
  EXPECT_EQ(q.loaded.resolved, continuous.resolved);
}

// The directory is checked between the scene's checks and the calibrations' cost: a
// refused scene never reaches it, and an accepted one reaches it before any calibration
// speaks.
TEST(PreparedScene, ChecksComeBeforeTheDirectoryAndTheCalibrations) {
  std::vector<std::string> events;
  PrepareOptions how;
  how.say = [&](const std::string& line) { events.push_back("say: " + line); };
  how.checked = [&] {
    events.push_back("checked");
    return Backend::default_space;
  };
  prepare_scene(parse_scene(testing::small_scene(), kDiscrete), how);
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.front(), "checked");
  EXPECT_NE(events[1].find("restitution of"), std::string::npos) << events[1];

  events.clear();
  // 1e-4 s is past the time-step guard's stable limit for the paper's steel (refused).
  EXPECT_THROW(prepare_scene(parse_scene(testing::small_scene(), {"time.dt=1e-4"}), how),
               UserError);
  EXPECT_TRUE(events.empty()) << events.front();
}

// --dry-run prints the scene and warnings the run's preparation makes (without the inlet
// calibration's channel runs, which it says it leaves out).
TEST(PreparedScene, DryRunReportsWhatTheRunPrepares) {
  testing::TempDir tmp;
  const auto scene = tmp.write("small.toml", testing::small_scene());
  // Past t_c/10 (2.45e-7 s for steel at the scene's fastest impact, 2.8 m/s) but within
  // the stable limit (7.47e-7 s): the guard warns.
  const std::vector<std::string> sets = {"contact.restitution_mode=discrete", "time.dt=4e-7"};
  RunOptions o = testing::run_options(scene, tmp.path() / "run", sets);
  o.dry_run = true;
  const RunCheck dry = check_run(o);
  const PreparedScene p = prepare_scene(load_scene_file(scene, sets), {});
  EXPECT_EQ(dry.resolved_scene, p.loaded.resolved);
  EXPECT_EQ(dry.warnings, p.warnings);
  ASSERT_FALSE(p.warnings.empty()) << "no warning to compare: choose a larger dt";
  EXPECT_FALSE(dry.calibrates_inflow);
}

// inflow.mach_at = "inlet_bins": the calibrated sigma is the scene's and its resolved
// TOML's (what run.h5 and the checkpoint store); --dry-run's preparation leaves the first
// guess (testing::fast_inlet_scene keeps the channel runs short).
TEST(PreparedScene, InletSigmaIsInTheResolvedScene) {
  const LoadedScene loaded = parse_scene(testing::fast_inlet_scene());

  PrepareOptions dry;
  dry.calibrate_inflow = false;
  const PreparedScene first_guess = prepare_scene(loaded, dry);
  EXPECT_FALSE(first_guess.inlet.has_value());
  EXPECT_EQ(first_guess.scene().inflow.sigma, loaded.scene.inflow.sigma);
  EXPECT_EQ(first_guess.loaded.resolved, loaded.resolved);

  const PreparedScene p = prepare_scene(loaded, {});
  ASSERT_TRUE(p.inlet.has_value());
  EXPECT_EQ(p.scene().inflow.sigma, p.inlet->sigma);
  EXPECT_NE(p.inlet->sigma, loaded.scene.inflow.sigma);
  EXPECT_EQ(parse_scene(p.loaded.resolved).scene.inflow.sigma, p.inlet->sigma);
  EXPECT_EQ(p.loaded.as_given, loaded.as_given);
}

}  // namespace
}  // namespace granshock

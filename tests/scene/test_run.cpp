// `granshock run` end to end (docs/output_format.md, docs/scene_format.md): mass balance,
// bitwise resume, bad input leaving no output, and the default scene's bow shock.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/run_file.hpp"
#include "run_helpers.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::read_json;
using granshock::testing::run_options;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

std::vector<double> series(const RunFile& f, const std::string& name) {
  return f.read_array("/observables/" + name + "/value");
}

}  // namespace

TEST(RunMassBalance, InsertedMinusDeletedIsPresentAtEveryOutput) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  ASSERT_EQ(run_scene(run_options(scene, tmp.path() / "run")), 0);
  const RunFile f = RunFile::open_read_only(tmp.path() / "run" / "run.h5");
  const auto present = series(f, "particles"), inserted = series(f, "inserted");
  const auto outlet = series(f, "deleted_outlet"), inlet = series(f, "deleted_inlet");
  ASSERT_EQ(present.size(), 21u);  // every 0.5 ms over 10 ms, and step 0
  for (std::size_t k = 0; k < present.size(); ++k)
    EXPECT_EQ(inserted[k] - outlet[k] - inlet[k], present[k]) << "row " << k;
  EXPECT_GT(outlet.back(), 0) << "particles must leave through the outlet";
  // Bounded: the channel holds ~phi_inf W L / (pi d^2/4) = 306 particles upstream.
  EXPECT_LT(*std::max_element(present.begin(), present.end()), 600);
}

TEST(RunResume, InterruptedAndResumedEqualsUninterruptedBitwise) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const std::vector<std::string> sets = {"time.duration=0.004", "time.production_start=0.002"};
  // Stopped at 7001, not a checkpoint step (those are multiples of 20 000).
  granshock::testing::run_straight_and_split(
      [&](const char* dir) { return run_options(scene, tmp.path() / dir, sets); }, 7001);

  CheckpointExtras ea, eb;
  const SolverState a = read_checkpoint(tmp.path() / "straight" / "checkpoint.h5", ea);
  const SolverState b = read_checkpoint(tmp.path() / "split" / "checkpoint.h5", eb);
  EXPECT_EQ(a.step, 20000);
  granshock::testing::expect_bitwise_equal_states(a, b, "resumed against uninterrupted");
  EXPECT_EQ(ea.inserted, eb.inserted);
  EXPECT_EQ(ea.deleted_outlet, eb.deleted_outlet);
  // The CPU time of every leg is recorded (summary.json cpu_seconds, the trade table's
  // cost): the last checkpoint holds the legs up to it, the summary all of them.
  EXPECT_GT(ea.cpu_seconds_so_far, 0);
  EXPECT_GT(eb.cpu_seconds_so_far, 0);
  for (const auto& [dir, extras] : {std::pair{"straight", ea}, std::pair{"split", eb}}) {
    const nlohmann::json j = read_json(tmp.path() / dir / "summary.json");
    ASSERT_TRUE(j["cpu_seconds"].is_number()) << dir;
    EXPECT_GE(j["cpu_seconds"].get<double>(), extras.cpu_seconds_so_far) << dir;
  }
  const RunFile fa = RunFile::open_read_only(tmp.path() / "straight" / "run.h5");
  const RunFile fb = RunFile::open_read_only(tmp.path() / "split" / "run.h5");
  for (const char* name : {"particles", "kinetic_energy", "temperature", "contacts", "inserted"})
    EXPECT_EQ(series(fa, name), series(fb, name)) << name;
  EXPECT_EQ(fa.frames().size(), fb.frames().size());
}

struct BadRun {
  const char* name;
  std::vector<std::string> sets;
  const char* expected;
};

class RunRefuses : public ::testing::TestWithParam<BadRun> {};

TEST_P(RunRefuses, WithOneMessageAndNoOutput) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path out = tmp.path() / "out";
  try {
    run_scene(run_options(scene, out, GetParam().sets));
    FAIL() << "accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out)) << "a refused run must not write anything";
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, RunRefuses,
    ::testing::Values(
        BadRun{"dt_past_stable_limit", {"time.dt=5e-6"}, "past the stable limit"},
        BadRun{"unknown_key", {"time.dtt=1"}, "unknown key"},
        BadRun{"phi_out_of_range", {"inflow.area_fraction=0.8"}, "must be in (0, 0.4]"},
        // Untrusted input (docs/scene_format.md): counts that overflowed.
        BadRun{
            "duration_overflows_steps", {"time.duration=1e13"}, "5e+19 steps, more than the 1e+12"},
        BadRun{"dt_tiny", {"time.dt=1e-30"}, "steps, more than the 1e+12"},
        BadRun{"shorter_than_a_step",
               {"time.duration=1e-7", "time.production_start=0"},
               "shorter than one time step"},
        BadRun{"snapshots_every_step",
               {"output.snapshot_interval=1e-12"},
               "write a particle snapshot"},
        // 1 km x 10 km, within the range of lengths (at most 10 km each).
        BadRun{"huge_domain",
               {"domain.width=\"1e6 d\"", "domain.length=\"1e7 d\""},
               "more than the 2.68e+08 one process holds"},
        // A custom material so soft that impacts overlap by a diameter.
        BadRun{"overlap_past_the_contact_law",
               {"materials.soft.youngs_modulus=1000", "materials.soft.poisson_ratio=0.3",
                "materials.soft.density=7850", "species.0.material=\"soft\"",
                "species.1.material=\"soft\""},
               "past 0.2 of a diameter the contact law has no meaning"},
        // The field sampling (docs/fields.md, "Up-front checks"): refused before
        // the run, not found empty after it.
        BadRun{"one_field_sample", {"output.sample_every=1000000000"}, "holds 1 field samples"},
        BadRun{"one_bin", {"numerics.bin_size=1000 d"}, "bins across the domain"},
        BadRun{"bins_below_a_particle",
               {"numerics.bin_size=0.001 d"},
               "smaller than the particle diameter"},
        BadRun{"blocks_beyond_limit", {"output.blocks=1000000000"}, "must be at most 10000"},
        BadRun{
            "unknown_restitution_mode", {"contact.restitution_mode=\"exact\""}, "restitution_mode"},
        // docs/stability.md: a step the guard accepts (at the fastest impact, 2.8 m/s) but at
        // which no damping returns e = 0.01 for impacts at 50 m/s (dt/t_c = 0.36).
        BadRun{"discrete_restitution_unreachable",
               {"contact.restitution_mode=\"discrete\"", "contact.restitution=0.01",
                "contact.calibration_speed=50", "time.dt=5e-7"},
               "no damping makes the steel-steel pair return e = 0.01"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

// docs/contact_model.md: contact.restitution_mode = "discrete" calibrates every pair at the run's
// dt, reports it in summary.json, changes the trajectory (the kernels run with the calibrated
// damping) and resumes bitwise (the calibration is a pure function of the scene).
TEST(RunDiscreteRestitution, CalibratedReportedUsedAndResumedBitwise) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const std::vector<std::string> base = {"time.duration=0.004", "time.production_start=0.002"};
  std::vector<std::string> discrete = base;
  discrete.push_back("contact.restitution_mode=\"discrete\"");
  ASSERT_EQ(run_scene(run_options(scene, tmp.path() / "continuous", base)), 0);
  ASSERT_EQ(run_scene(run_options(scene, tmp.path() / "discrete", discrete)), 0);
  RunOptions first = run_options(scene, tmp.path() / "split", discrete);
  first.stop_after_steps = 7001;
  ASSERT_EQ(run_scene(first), 0);
  RunOptions second = run_options(scene, tmp.path() / "split", discrete);
  second.resume = true;
  ASSERT_EQ(run_scene(second), 0);

  const nlohmann::json j = read_json(tmp.path() / "discrete" / "summary.json");
  const nlohmann::json& c = j.at("restitution_calibration");
  EXPECT_EQ(c.at("mode"), "discrete");
  ASSERT_EQ(c.at("pairs").size(), 5u) << c.dump();  // 3 particle pairs, 2 with the obstacle
  for (const auto& [pair, p] : c.at("pairs").items()) {
    EXPECT_NEAR(p.at("e_eff").get<double>(), p.at("e").get<double>(), 1e-9) << pair;
    EXPECT_NE(p.at("beta").get<double>(), p.at("beta_continuous").get<double>()) << pair;
    EXPECT_EQ(p.at("residual_over_speed").size(), 4u) << pair;
  }
  EXPECT_TRUE(read_json(tmp.path() / "continuous" / "summary.json")
                  .at("restitution_calibration")
                  .is_null());

  CheckpointExtras e1, e2, e3;
  const SolverState cont = read_checkpoint(tmp.path() / "continuous" / "checkpoint.h5", e1);
  const SolverState disc = read_checkpoint(tmp.path() / "discrete" / "checkpoint.h5", e2);
  const SolverState split = read_checkpoint(tmp.path() / "split" / "checkpoint.h5", e3);
  EXPECT_NE(cont.velocity, disc.velocity) << "the calibrated damping did not reach the kernels";
  EXPECT_EQ(disc.velocity, split.velocity) << "a resumed discrete run is not bitwise equal";
  EXPECT_EQ(disc.position, split.position);
}

// --slice-steps (docs/design.md, "run"): slices of 7 steps call the solver about 2,900
// times where the wall-clock slices call it about 110 times (every sample, series row and
// output), and the run is bitwise the same: a call of advance() ends and starts with the
// same arithmetic as the steps inside one.
TEST(RunSlices, FixedSlicesOfStepsGiveTheSameRunBitwise) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const std::vector<std::string> sets = {"time.duration=0.004", "time.production_start=0.002"};
  ASSERT_EQ(run_scene(run_options(scene, tmp.path() / "timed", sets)), 0);
  RunOptions sliced = run_options(scene, tmp.path() / "sliced", sets);
  sliced.slice_steps = 7;
  ASSERT_EQ(run_scene(sliced), 0);

  CheckpointExtras ea, eb;
  const SolverState a = read_checkpoint(tmp.path() / "timed" / "checkpoint.h5", ea);
  const SolverState b = read_checkpoint(tmp.path() / "sliced" / "checkpoint.h5", eb);
  EXPECT_EQ(a.step, 20000);
  granshock::testing::expect_bitwise_equal_states(a, b, "slices of 7 steps");
  EXPECT_EQ(ea.bin_sums, eb.bin_sums) << "the field sums differ";
  const RunFile fa = RunFile::open_read_only(tmp.path() / "timed" / "run.h5");
  const RunFile fb = RunFile::open_read_only(tmp.path() / "sliced" / "run.h5");
  for (const char* name : {"particles", "kinetic_energy", "temperature", "contacts", "inserted"})
    EXPECT_EQ(series(fa, name), series(fb, name)) << name;

  // Each call launches at least its first half kick and its closing pass, so slices of 7
  // steps launch at least 2/7 kernels per step; the timed run's calls end about every 100
  // steps in the production half and every 2,500 before it.
  const auto launches = [&](const char* dir) {
    const nlohmann::json j = read_json(tmp.path() / dir / "summary.json");
    return j.at("kernel_launches_per_step").get<double>();
  };
  EXPECT_GE(launches("sliced"), 2.0 / 7.0);
  EXPECT_LT(launches("timed"), 0.5 * launches("sliced"));
}

TEST(RunRefusesDirectory, UnwritableOrExisting) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const auto file = tmp.write("a-file", "x");
  EXPECT_THROW(run_scene(run_options(scene, file / "out")), UserError);  // parent is a file
  EXPECT_FALSE(fs::exists(file / "out"));
  fs::create_directories(tmp.path() / "old");
  tmp.write("old/run.h5", "previous results");
  try {
    run_scene(run_options(scene, tmp.path() / "old"));
    FAIL() << "an existing run directory was overwritten without --overwrite";
  } catch (const UserError& e) {
    // Unmarked (granshock before 0.2): refused even with --overwrite
    // (test_run_directory.cpp).
    EXPECT_NE(std::string(e.what()).find("perhaps from a granshock before 0.2"), std::string::npos)
        << e.what();
  }
  RunOptions resume = run_options(scene, tmp.path() / "nothing-here");
  resume.resume = true;
  EXPECT_THROW(run_scene(resume), UserError);
}

// Test 6: the default scene at reduced length forms a dense region in front of the
// cylinder: the area fraction in a box D wide and 5 d deep just upstream of it is at
// least twice phi_inf (averaged over the last two snapshots).
TEST(RunDefaultScene, FormsADenseRegionInFrontOfTheObstacle) {
  TempDir tmp;
  const fs::path scene = fs::path(GRANSHOCK_SOURCE_DIR) / "scenes" / "default.toml";
  ASSERT_EQ(run_scene(run_options(scene, tmp.path() / "run",
                                  {"time.duration=0.04", "time.production_start=0.02",
                                   "output.snapshot_interval=0.01"})),
            0);
  const RunFile f = RunFile::open_read_only(tmp.path() / "run" / "run.h5");
  const auto frames = f.frames();
  ASSERT_GE(frames.size(), 3u);
  const double d = 1e-3, xc = 0.075, yc = 0.120, radius = 0.010;
  const auto positions = f.read_array("/particles/all/position/value");
  const long cap = f.particle_capacity();
  double phi = 0;
  for (std::size_t k = frames.size() - 2; k < frames.size(); ++k) {
    double area = 0;
    for (long i = 0; i < frames[k].count; ++i) {
      const double x = positions[(k * cap + i) * 2], y = positions[(k * cap + i) * 2 + 1];
      if (std::abs(x - xc) < radius && y > yc - radius - 5 * d && y < yc - radius)
        area += M_PI * d * d / 4;
    }
    phi += area / (2 * radius * 5 * d) / 2;
  }
  std::printf("[ measured ] area fraction in front of the cylinder %.3f (phi_inf 0.1)\n", phi);
  EXPECT_GE(phi, 0.2);
}

// docs/design.md, "Stability": past the stable limit (forced), the run does not produce garbage
// silently: it stops with a diagnosis naming dt and t_c.
TEST(RunStability, ForcedUnstableStepStopsWithADiagnosis) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  // Samples every 10 steps: at this dt the default 100 would leave the production window too
  // few field samples, and the run would be refused before it could blow up.
  RunOptions o = run_options(scene, tmp.path() / "run", {"time.dt=3e-6", "output.sample_every=10"});
  o.force = true;
  try {
    run_scene(o);
    FAIL() << "a run at dt = 1.2 t_c finished without a diagnosis";
  } catch (const NumericalFailure& e) {
    EXPECT_NE(std::string(e.what()).find("blew up"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reduce time.dt"), std::string::npos) << e.what();
  }
}

// docs/stability.md: an inflow that cannot be met is reported, not carried forward
// without end. phi_inf = 0.4 (the limit) into a 30 d channel nearly closed by a cylinder
// of 26 d, e = 0.2: the particles it stops pile up into the strip, and the narrow gaps
// beside it cannot take the prefill. summary.json tells requested, inserted, backlog and
// lost, the backlog stays bounded by one batch, and stderr warns once.
TEST(RunInflow, AStripThatStaysFullIsReportedAndItsBacklogBounded) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  RunOptions o = run_options(
      scene, tmp.path() / "blocked",
      {"inflow.area_fraction=0.4", "inflow.velocity=0.5", "inflow.sigma=0.05",
       "contact.restitution=0.2", "domain.width=\"30 d\"", "domain.length=\"40 d\"",
       "obstacle.centre=[\"15 d\", \"20 d\"]", "obstacle.diameter=\"26 d\"", "time.duration=0.04",
       "time.production_start=0.02", "numerics.bin_size=\"1 d\""});
  ::testing::internal::CaptureStderr();
  ASSERT_EQ(run_scene(o), 0);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("warning: the inflow falls short"), std::string::npos) << err;
  const auto blocked = read_json(tmp.path() / "blocked" / "summary.json")["inflow"];
  std::printf("[ measured ] blocked inlet: %s\n", blocked.dump().c_str());
  EXPECT_TRUE(blocked["falls_short"].get<bool>());
  EXPECT_LT(blocked["achieved_fraction"].get<double>(), 0.97);
  // Bounded: one batch of a 30 d strip at phi 0.4 is 0.4 * 30 * 2 / (pi / 4) = 30.6
  // particles.
  EXPECT_LE(blocked["backlog"].get<double>(), 0.4 * 30 * 2 / (M_PI / 4) * 1.001);
  EXPECT_NEAR(blocked["requested"].get<double>(),
              blocked["inserted"].get<double>() + blocked["backlog"].get<double>() +
                  blocked["lost"].get<double>(),
              1e-6);

  ASSERT_EQ(run_scene(run_options(
                scene, tmp.path() / "free",
                {"time.duration=0.002", "time.production_start=0.001", "output.sample_every=10"})),
            0);
  const auto free = read_json(tmp.path() / "free" / "summary.json")["inflow"];
  EXPECT_FALSE(free["falls_short"].get<bool>()) << free.dump();
  EXPECT_GT(free["achieved_fraction"].get<double>(), 0.99) << free.dump();
}

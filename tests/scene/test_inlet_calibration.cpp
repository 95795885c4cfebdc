// The inflow of the paper's scenes against the paper's Table 1 (docs/fields.md, "Three
// upstream Mach numbers"): the paper measures Ma_inf over the two bin rows next to the
// inlet with m = sum_a m_a (its eqs. 6-7). The paper scenes ask for that Mach number
// (inflow.mach_at = "inlet_bins"): sigma is calibrated in an obstacle-free inlet channel
// (cases/bow_shock/inlet_calibration.hpp), and the measured Ma must then meet 2.64, 5.9
// and 13.7 within 3 % in a second channel run with another seed, i.e. beyond the noise the
// calibration was fitted to. The channel is the scene's 500 d wide and 4 bins (12 d) long.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cases/bow_shock/inlet_calibration.hpp"
#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/scene_file.hpp"
#include "run_helpers.hpp"
#include "scene_fixtures.hpp"

namespace granshock {
namespace {

struct PaperInflow {
  const char* scene;
  double mach;  // Table 1
};

Scene paper_scene(const char* file) {
  return load_scene_file(std::string(GRANSHOCK_SOURCE_DIR) + "/scenes/paper/" + file, {}).scene;
}

class PaperInflows : public ::testing::TestWithParam<PaperInflow> {};

TEST_P(PaperInflows, MeetTheTableOneMachNumberAtTheInletRows) {
  Scene s = paper_scene(GetParam().scene);
  ASSERT_EQ(s.inflow.mach_at, MachReference::inlet_bins);
  ASSERT_EQ(s.mass_definition, MassDefinition::paper_sum);
  ASSERT_DOUBLE_EQ(*s.inflow.target_mach, GetParam().mach);
  const InletCalibration cal = calibrate_inlet_mach(s);
  ASSERT_TRUE(cal.converged);
  EXPECT_LE(cal.tolerance, 0.03);
  EXPECT_LE(std::abs(cal.iterations.back().mach / cal.target - 1), cal.tolerance);
  for (const InletMach& m : cal.iterations)
    std::printf("  sigma %.4f m/s: Ma %.3f +- %.3f (mixture mean %.3f), phi %.4f, %.3g s\n",
                m.sigma, m.mach, m.mach_err, m.mach_mixture_mean, m.phi, m.simulated_s);
  s.run.seed += 1000;
  const InletMach check = measure_inlet_mach(s, cal.sigma);
  std::printf("  inserted-convention sigma %.4f, calibrated %.4f; another seed: Ma %.3f +- %.3f\n",
              cal.sigma_inserted, cal.sigma, check.mach, check.mach_err);
  EXPECT_NEAR(check.mach / GetParam().mach, 1.0, 0.03);
  // At the slowest inflow the gas cools on its way to the inlet rows: the inserted
  // convention misses the measured Ma by more than 5 %, a gap the calibration must close.
  if (GetParam().mach < 3) {
    EXPECT_GT(std::abs(cal.iterations.front().mach / cal.target - 1), 0.05);
    EXPECT_GE(cal.iterations.size(), 2u);
  }
}

INSTANTIATE_TEST_SUITE_P(TableOne, PaperInflows,
                         ::testing::Values(PaperInflow{"d50_u0475.toml", 2.64},
                                           PaperInflow{"d50_u1000.toml", 5.9},
                                           PaperInflow{"d50_u2375.toml", 13.7}));

// End to end: a run with inflow.mach_at = "inlet_bins" calibrates, uses and reports the
// calibrated sigma, and a run stopped and resumed recomputes the same sigma bit for bit
// and so ends in the same state as one run straight through. A wide, fast inflow keeps
// the calibration short (about 0.08 s simulated per channel run).
TEST(InletCalibration, RunUsesReportsAndResumesTheCalibratedSigma) {
  testing::TempDir tmp;
  const std::string text = testing::fast_inlet_scene();
  const auto scene = tmp.write("fast.toml", text);
  const std::vector<std::string> sets = {"time.duration=0.004", "time.production_start=0.002",
                                         "output.sample_every=20"};
  granshock::testing::run_straight_and_split(
      [&](const char* dir) {
        return granshock::testing::run_options(scene, tmp.path() / dir, sets);
      },
      3001);

  std::ifstream in(tmp.path() / "straight" / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& cal = j["inflow_calibration"];
  ASSERT_TRUE(cal.is_object());
  EXPECT_TRUE(cal["converged"].get<bool>());
  EXPECT_EQ(j["inflow_mach_at"], "inlet_bins");
  EXPECT_EQ(j["inflow_sigma"].get<double>(), cal["sigma"].get<double>());
  EXPECT_NE(cal["sigma"].get<double>(), cal["sigma_inserted"].get<double>());
  EXPECT_EQ(j["ma_inf_deviation_rows"], "inlet");
  for (const nlohmann::json& it : cal["iterations"])
    std::printf("  sigma %.4f m/s: Ma %.3f +- %.3f\n", it["sigma"].get<double>(),
                it["mach"].get<double>(), it["mach_err"].get<double>());

  CheckpointExtras ea, eb;
  const SolverState a = read_checkpoint(tmp.path() / "straight" / "checkpoint.h5", ea);
  const SolverState b = read_checkpoint(tmp.path() / "split" / "checkpoint.h5", eb);
  // The resolved scene carries the sigma the run used.
  const Scene resolved = parse_scene(ea.scene_resolved).scene;
  EXPECT_EQ(resolved.inflow.sigma, cal["sigma"].get<double>());
  EXPECT_EQ(ea.scene_resolved, eb.scene_resolved);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.position, b.position) << "the resumed run is not bitwise equal";
  EXPECT_EQ(a.velocity, b.velocity);
}

TEST(InletCalibration, NeedsATargetMachNumber) {
  std::string text = testing::small_scene(false);
  text.replace(text.find("sigma = 0.1"), 11, "sigma = 0.1\nmach_at = \"inlet_bins\"");
  try {
    parse_scene(text);
    FAIL() << "inflow.mach_at = inlet_bins without inflow.mach was accepted";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("inflow.mach_at"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_scene(testing::small_scene(false), {"inflow.mach_at=inlet"}), UserError);
}

}  // namespace
}  // namespace granshock

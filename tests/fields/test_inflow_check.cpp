// The measured upstream state against the scene's target (docs/fields.md, "Inflow against
// target"): phi_inf beyond the strip against inflow.area_fraction and Ma_inf against the
// target, as relative deviations, and a warning when phi_inf falls more than 5 % short.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/field_analysis.hpp"
#include "analysis/fields_command.hpp"
#include "analysis/fields_output.hpp"
#include "synthetic_run.hpp"

using namespace granshock;

namespace {

constexpr double kD = 1e-3;

// Uniform upstream flow at Ma 6 over the whole 60 d x 90 d channel of a scene with target
// phi_inf 0.3 (no obstacle, so every row is upstream); block b holds phi[b].
FieldAnalysis analyse_uniform(const std::vector<double>& phi, double target_phi = 0.3) {
  const std::string toml = test::bow_shock_scene(0, 5.9, target_phi);
  const FieldPhysics phys = test::physics_of(toml);
  BinSums grid = test::empty_sums(20, 30, static_cast<int>(phi.size()), 0, 0, 3 * kD, 3 * kD);
  for (std::size_t b = 0; b < phi.size(); ++b) {
    const test::BinState st = test::mixture_state(
        phys, phi[b], test::temperature_for_mach(phys, phi[b], 1.0, 6.0), 0, 1.0);
    grid.samples[b] = 500;
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix)
        test::add_state(grid, static_cast<int>(b), iy, ix, st, phys, 500);
  }
  return analyse_fields(parse_scene(toml).scene, grid, std::nullopt);
}

}  // namespace

TEST(InflowCheck, PhiShortOfTheTargetRaisesTheFlag) {
  const FieldAnalysis a = analyse_uniform({0.21, 0.21});
  const InflowCheck& c = a.inflow;
  EXPECT_NEAR(c.phi_measured, 0.21, 1e-12);
  EXPECT_NEAR(c.phi_target, 0.3, 1e-12);
  EXPECT_NEAR(c.phi_deviation, -0.3, 1e-9);
  EXPECT_TRUE(c.phi_short);
  EXPECT_NE(c.warning.find("30.0 % below the target inflow.area_fraction = 0.3"), std::string::npos)
      << c.warning;
  EXPECT_NE(c.warning.find("significant"), std::string::npos) << c.warning;  // error 0
  // Ma: measured 6 (the state's temperature) against the target 5.9.
  EXPECT_NEAR(c.ma_deviation, 6.0 / 5.9 - 1, 1e-9);

  const nlohmann::json j = summary_keys(a);
  EXPECT_TRUE(j["inflow_phi_short"].get<bool>());
  EXPECT_NEAR(j["phi_inf_deviation"].get<double>(), -0.3, 1e-9);
  EXPECT_NEAR(j["phi_inf_target"].get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(j["ma_inf_deviation"].get<double>(), 6.0 / 5.9 - 1, 1e-9);
  EXPECT_TRUE(j["inflow_warning"].is_string());
  EXPECT_NEAR(j["phi_inf_measured_downstream_err"].get<double>(), 0.0, 1e-12);
}

TEST(InflowCheck, ToleranceIsFivePercent) {
  EXPECT_FALSE(analyse_uniform({0.29, 0.29}).inflow.phi_short);  // 3.3 % short
  EXPECT_FALSE(analyse_uniform({0.33, 0.33}).inflow.phi_short);  // 10 % over: not short
  const FieldAnalysis a = analyse_uniform({0.2835, 0.2835});     // 5.5 % short
  EXPECT_TRUE(a.inflow.phi_short);
  EXPECT_TRUE(summary_keys(analyse_uniform({0.3, 0.3}))["inflow_warning"].is_null());
}

TEST(InflowCheck, ShortfallIsComparedWithTheBlockError) {
  // Blocks at 0.20 and 0.22: error 0.01, shortfall 0.09 = 9 errors.
  const FieldAnalysis sig = analyse_uniform({0.20, 0.22});
  EXPECT_NEAR(sig.phi_up_err, 0.01, 1e-9);
  EXPECT_TRUE(sig.inflow.phi_short);
  EXPECT_NE(sig.inflow.warning.find("significant"), std::string::npos) << sig.inflow.warning;
  // Blocks at 0.24 and 0.30: error 0.03, shortfall 0.03 = 1 error; flagged (10 % short) but
  // said to be within the noise.
  const FieldAnalysis noisy = analyse_uniform({0.24, 0.30});
  EXPECT_TRUE(noisy.inflow.phi_short);
  EXPECT_NE(noisy.inflow.warning.find("within 2 errors"), std::string::npos)
      << noisy.inflow.warning;
  // One block: no error, and the warning says so.
  const FieldAnalysis one = analyse_uniform({0.21});
  EXPECT_TRUE(one.inflow.phi_short);
  EXPECT_NE(one.inflow.warning.find("no statistical error"), std::string::npos)
      << one.inflow.warning;
  EXPECT_TRUE(summary_keys(one)["phi_inf_measured_downstream_err"].is_null());
}

TEST(InflowCheck, FieldsCommandWarnsOnStderr) {
  test::ScratchDir tmp;
  const std::string toml = test::bow_shock_scene(0, 5.9, 0.3);
  const FieldPhysics phys = test::physics_of(toml);
  BinSums grid = test::empty_sums(20, 30, 2, 0, 0, 3 * kD, 3 * kD);
  const test::BinState st =
      test::mixture_state(phys, 0.21, test::temperature_for_mach(phys, 0.21, 1.0, 6.0), 0, 1.0);
  test::fill_with_front(
      grid, phys, st, st, [](double, double, int) { return false; }, 300, 2);
  test::write_run_file(tmp.path() / "run", toml, grid, nullptr);
  ::testing::internal::CaptureStderr();
  fields_command({tmp.path() / "run"}, {}, FieldsCommandOptions{false, true});
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("granshock: warning: "), std::string::npos) << err;
  EXPECT_NE(err.find("below the target inflow.area_fraction"), std::string::npos) << err;
  std::ifstream in(tmp.path() / "run" / "summary.json");
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str());
  EXPECT_TRUE(j["inflow_phi_short"].get<bool>());
  EXPECT_TRUE(j["inflow_warning"].is_string());
}

TEST(InflowCheck, NoUpstreamStateNoVerdict) {
  // Every bin masked: nothing to compare, nothing flagged, and the reasons say why.
  const std::string toml = test::bow_shock_scene(0, 5.9, 0.3);
  const FieldPhysics phys = test::physics_of(toml);
  BinSums grid = test::empty_sums(20, 30, 2, 0, 0, 3 * kD, 3 * kD);
  const test::BinState st =
      test::mixture_state(phys, 0.21, test::temperature_for_mach(phys, 0.21, 1.0, 6.0), 0, 1.0);
  test::fill_with_front(
      grid, phys, st, st, [](double, double, int) { return false; }, 2, 2);
  const FieldAnalysis a = analyse_fields(parse_scene(toml).scene, grid, std::nullopt);
  EXPECT_FALSE(a.inflow.phi_short);
  EXPECT_TRUE(std::isnan(a.inflow.phi_deviation));
  EXPECT_NE(a.inflow.phi_deviation_reason.find("no upstream state beyond the strip"),
            std::string::npos)
      << a.inflow.phi_deviation_reason;
  const nlohmann::json j = summary_keys(a);
  EXPECT_TRUE(j["phi_inf_deviation"].is_null());
  EXPECT_TRUE(j["ma_inf_deviation_reason"].is_string());
}

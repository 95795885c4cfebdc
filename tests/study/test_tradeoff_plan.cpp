// The cases of `granshock tradeoff` (cases/tradeoff/tradeoff_plan.hpp) on the small channel
// of the run tests: every setting at the value docs/accuracy.md names, the sampling
// interval kept in simulated time, and a study file the study runner reads back.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "cases/bow_shock/run_checks.hpp"
#include "cases/study/study_file.hpp"
#include "cases/tradeoff/tradeoff_plan.hpp"
#include "io/scene_file.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;

namespace {

// The value of `key` in a case's overrides ("" when absent).
std::string value_of(const TradeCase& c, const std::string& key) {
  for (const std::string& o : c.overrides)
    if (o.rfind(key + "=", 0) == 0) return o.substr(key.size() + 1);
  return "";
}

}  // namespace

TEST(TradeoffPlan, EverySettingAtItsValue) {
  const Scene scene =
      parse_scene(granshock::testing::small_scene(true)).scene;  // dt 2e-7, every 100
  const TimeStepAssessment guard = assess_time_step(scene);
  std::map<std::string, TradeCase> cases;
  for (const TradeCase& c : tradeoff_cases(scene)) cases[c.name] = c;
  ASSERT_EQ(cases.size(), 22u);
  const auto dt = [&](const std::string& name) {
    return std::stod(value_of(cases[name], "time.dt"));
  };
  const auto every = [&](const std::string& name) {
    return std::stol(value_of(cases[name], "output.sample_every"));
  };
  EXPECT_NEAR(dt("reference"), guard.t_c / 100, 1e-6 * guard.t_c / 100);
  EXPECT_NEAR(dt("dt-tc6"), guard.t_c / 6, 1e-6 * guard.t_c / 6);
  EXPECT_NEAR(dt("dt-stable"), 0.95 * guard.dt_stable, 1e-6 * guard.dt_stable);
  EXPECT_EQ(dt("scene"), 2e-7);
  // The fields are sampled every 2e-5 s of simulated time in every case.
  for (const char* name : {"reference", "dt-tc50", "dt-tc25", "scene", "dt-tc6", "dt-stable"})
    EXPECT_NEAR(every(name) * dt(name), 100 * 2e-7, 0.5 * dt(name)) << name;
  // Softening keeps dt / t_c: dt grows as F^(2/5).
  EXPECT_EQ(value_of(cases["soft-1000"], "contact.softening"), "1000");
  EXPECT_NEAR(dt("soft-1000"), 2e-7 * std::pow(1000.0, 0.4), 1e-12);
  EXPECT_EQ(value_of(cases["single"], "numerics.precision"), "\"single\"");
  EXPECT_NEAR(std::stod(value_of(cases["skin-0.1"], "numerics.skin")), 1e-4, 1e-12);
  // Four times sparser would leave 62 samples for 10 blocks: as sparse as 10 per block.
  EXPECT_EQ(value_of(cases["sample-sparse"], "output.sample_every"), "250");
  EXPECT_EQ(value_of(cases["window-half"], "time.production_start"), "0.0075");
  EXPECT_EQ(value_of(cases["seed-2"], "scene.seed"), "8");
  // The discrete mode alone and with each softening, at the softening's dt.
  EXPECT_EQ(value_of(cases["discrete"], "contact.restitution_mode"), "\"discrete\"");
  EXPECT_EQ(value_of(cases["soft-1000-discrete"], "contact.restitution_mode"), "\"discrete\"");
  EXPECT_EQ(value_of(cases["soft-1000-discrete"], "contact.softening"), "1000");
  EXPECT_EQ(dt("soft-1000-discrete"), dt("soft-1000"));
  // Four seeds of the scene as given, for the noise: its own settings and seeds 7 to 10.
  for (int k = 2; k <= 4; ++k) {
    const std::string name = "seed-" + std::to_string(k);
    EXPECT_EQ(cases[name].overrides,
              std::vector<std::string>{"scene.seed=" + std::to_string(6 + k)})
        << name;
  }
  // The reference with the second seed: the bias of the scene's setting on other particles.
  EXPECT_EQ(dt("reference-seed-2"), dt("reference"));
  EXPECT_EQ(value_of(cases["reference-seed-2"], "scene.seed"), "8");
  EXPECT_EQ(cases.count("reference-seed-3"), 0u);
}

TEST(TradeoffPlan, StudyFileReadsBackWithEveryCase) {
  const Scene scene = parse_scene(granshock::testing::small_scene(true)).scene;
  const std::vector<TradeCase> cases = tradeoff_cases(scene);
  const std::string toml =
      tradeoff_study_toml("tradeoff_small", "/scenes/small.toml", {"time.duration=0.02"}, cases);
  const StudySpec spec = parse_study(toml, "/tmp/tradeoff.toml");
  EXPECT_EQ(spec.name, "tradeoff_small");
  EXPECT_EQ(spec.base, "/scenes/small.toml");
  EXPECT_EQ(spec.mode, StudyMode::list);
  EXPECT_EQ(spec.common, std::vector<std::string>{"time.duration=0.02"});
  ASSERT_EQ(spec.cases.size(), cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    EXPECT_EQ(spec.cases[k].name, cases[k].name);
    EXPECT_EQ(spec.cases[k].overrides, cases[k].overrides);  // quotes survive
  }
}

// `granshock study --accuracy BUDGET` (docs/study.md, "An error budget"): each case's
// settings chosen for the budget on its own scene, exactly as `granshock run --accuracy`
// chooses them; certified only where the table was shown to hold; carried into the cost,
// the Slurm script and the study table.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cases/accuracy/accuracy_choice.hpp"
#include "cases/study/slurm_script.hpp"
#include "cases/study/study_cost.hpp"
#include "cases/study/study_file.hpp"
#include "cases/study/study_plan.hpp"
#include "cases/study/study_table.hpp"
#include "core/shell_text.hpp"
#include "io/scene_file.hpp"
#include "scene_fixtures.hpp"
#include "trade_table_fixture.hpp"

using namespace granshock;
using granshock::testing::fake_trade_table;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// Two cases of small_scene: D = 10 d and D = 30 d (Ma about 7.7 both), under `table`.
StudyPlan plan_with(const TempDir& tmp, const nlohmann::json& table, const std::string& budget) {
  const auto base = tmp.write("small.toml", small_scene(true));
  StudySpec spec = parse_study("[study]\nname = \"t\"\nbase = \"" + base.string() +
                                   "\"\n[[axis]]\nname = \"D\"\nkey = \"obstacle.diameter\"\n"
                                   "values = [\"10 d\", \"30 d\"]\n",
                               tmp.path() / "t.toml");
  spec.accuracy = StudySpec::Accuracy{budget, tmp.write("trade.json", table.dump())};
  return plan_study(spec, tmp.path() / "out");
}

}  // namespace

// Each case gets what `granshock run --accuracy` would give its own scene: the same
// overrides, appended to the case's, and the same record; its scene, and so its cost, is
// the chosen one.
TEST(StudyAccuracy, EachCaseIsChosenAsRunWouldChooseItsScene) {
  TempDir tmp;
  const StudyPlan plan = plan_with(tmp, fake_trade_table(), "5%");
  ASSERT_EQ(plan.cases.size(), 2u);
  for (const PlannedCase& c : plan.cases) {
    SCOPED_TRACE(c.spec.name);
    std::vector<std::string> own = run_overrides(plan.spec, c);
    const AccuracyChoice alone = choose_accuracy(
        plan.spec.base, {own.begin(), own.end() - long(c.accuracy_choice.at("overrides").size())},
        "5%", plan.spec.accuracy->table);
    EXPECT_EQ(c.accuracy_choice, alone.record);
    EXPECT_EQ(std::vector<std::string>(own.end() - long(alone.overrides.size()), own.end()),
              alone.overrides);
    EXPECT_EQ(c.accuracy_choice.at("case"), "soft-100");
    EXPECT_TRUE(c.accuracy_choice.at("certified").get<bool>());
    EXPECT_EQ(c.scene.setup.dt, c.accuracy_choice.at("dt").get<double>());
    EXPECT_EQ(c.scene.setup.contacts.softening, 100);
    EXPECT_FALSE(c.accuracy_report.empty());
    // The cost is the chosen scene's: its steps at the chosen dt.
    EXPECT_NEAR(expected_particle_steps(c.scene),
                expected_particles(c.scene) * double(c.scene.total_steps()),
                1e-9 * expected_particle_steps(c.scene));
    EXPECT_NEAR(double(c.scene.total_steps()), c.scene.run.duration_s / c.scene.setup.dt, 1.0);
  }
  // Each case's own t_c: the same dt/t_c, and D changes nothing of t_c here.
  EXPECT_EQ(plan.cases[0].accuracy_choice.at("dt_over_tc"),
            plan.cases[1].accuracy_choice.at("dt_over_tc"));
}

// Where the table was shown to hold on D/d 20 to 60 only, the D = 10 d case is not
// certified (it runs as given, not as the table's most accurate case, which would cost
// several times its own settings) while the D = 30 d case is.
TEST(StudyAccuracy, CertifiedCaseByCaseInsideTheTablesRange) {
  TempDir tmp;
  nlohmann::json table = fake_trade_table();
  table["certified_range"]["D_over_d"] = {20, 60};
  const StudyPlan plan = plan_with(tmp, table, "5%");
  const nlohmann::json& d10 = plan.cases[0].accuracy_choice;
  const nlohmann::json& d30 = plan.cases[1].accuracy_choice;
  EXPECT_FALSE(d10.at("certified").get<bool>());
  EXPECT_EQ(d10.at("case"), "scene as given");
  EXPECT_EQ(d10.at("dt"), d10.at("scene_dt"));
  EXPECT_EQ(d10.at("overrides"), nlohmann::json::array());
  EXPECT_EQ(d10.at("speedup_over_scene"), 1.0);
  EXPECT_TRUE(d30.at("certified").get<bool>());
  EXPECT_EQ(d30.at("case"), "soft-100");
  bool said = false;
  for (const std::string& line : plan.cases[0].accuracy_report)
    said |=
        line.find("cannot certify: not certified for this scene (D/d = 10,") != std::string::npos;
  EXPECT_TRUE(said);
}

// The Slurm tasks choose as the plan did: the budget and the table on every task's line.
TEST(StudyAccuracy, TheSlurmScriptCarriesTheBudgetAndTheTable) {
  TempDir tmp;
  const StudyPlan plan = plan_with(tmp, fake_trade_table(), "5%");
  const std::string text = slurm_script(plan, "/usr/bin/granshock", 1e8, "test").text;
  EXPECT_NE(
      text.find(" --accuracy '5%' --accuracy-table " +
                shell_quote(fs::absolute(plan.spec.accuracy->table).lexically_normal().string()) +
                " --case "),
      std::string::npos)
      << text;
}

// The study table lists each case's chosen settings beside its scene, run or not.
TEST(StudyAccuracy, TheStudyTableListsTheChosenSettings) {
  TempDir tmp;
  nlohmann::json table = fake_trade_table();
  table["certified_range"]["D_over_d"] = {20, 60};
  const StudyTable t = study_table(plan_with(tmp, table, "5%"), {});
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0]["accuracy.case"], "scene as given");
  EXPECT_EQ(t.rows[0]["accuracy.certified"], false);
  EXPECT_EQ(t.rows[1]["accuracy.case"], "soft-100");
  EXPECT_EQ(t.rows[1]["accuracy.softening"], 100.0);
  EXPECT_EQ(t.rows[1]["accuracy.precision"], "double");
  for (const char* column : {"accuracy.case", "accuracy.certified", "accuracy.dt_over_tc"})
    EXPECT_NE(std::find(t.columns.begin(), t.columns.end(), column), t.columns.end()) << column;
}

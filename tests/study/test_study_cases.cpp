// The cases of a study (docs/study.md, "Cases"): product, list and sweep, their names and
// overrides, and the refusals that keep a study from running what the user did not mean.
#include <gtest/gtest.h>

#include "cases/study/study_plan.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;
using granshock::testing::TempDir;

namespace {

StudySpec spec(const std::string& mode_and_axes, const std::string& base = "scene.toml") {
  return parse_study("[study]\nname = \"s\"\nbase = \"" + base + "\"\n" + mode_and_axes, "s.toml");
}

const std::string kTwoAxes = R"(
[[axis]]
name = "phi"
key = "inflow.area_fraction"
values = [0.05, 0.1, 0.2]
[[axis]]
name = "e"
key = "contact.restitution"
values = [0.5, 0.9]
)";

std::vector<std::string> names(const std::vector<StudyCase>& cases) {
  std::vector<std::string> out;
  for (const StudyCase& c : cases) out.push_back(c.name);
  return out;
}

std::string error_of(const StudySpec& s) {
  try {
    expand_cases(s);
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(StudyCases, ProductTakesEveryCombinationTheFirstAxisSlowest) {
  const auto cases = expand_cases(spec(kTwoAxes));
  EXPECT_EQ(names(cases),
            (std::vector<std::string>{"phi-0.05_e-0.5", "phi-0.05_e-0.9", "phi-0.1_e-0.5",
                                      "phi-0.1_e-0.9", "phi-0.2_e-0.5", "phi-0.2_e-0.9"}));
  EXPECT_EQ(cases[3].overrides,
            (std::vector<std::string>{"inflow.area_fraction=0.1", "contact.restitution=0.9"}));
  EXPECT_EQ(cases[3].axis_value, (std::vector<int>{1, 1}));
  for (std::size_t k = 0; k < cases.size(); ++k) EXPECT_EQ(cases[k].index, int(k));
}

TEST(StudyCases, ListTakesTheKthValuesTogetherAndNeedsEqualLengths) {
  const auto cases = expand_cases(spec(std::string("mode = \"list\"\n") + R"(
[[axis]]
name = "U"
key = "inflow.velocity"
values = [0.5, 1.0]
[[axis]]
name = "Ma"
key = "inflow.mach"
values = [3.0, 6.0]
)"));
  EXPECT_EQ(names(cases), (std::vector<std::string>{"U-0.5_Ma-3.0", "U-1.0_Ma-6.0"}));
  const std::string e = error_of(spec("mode = \"list\"\n" + kTwoAxes));
  EXPECT_NE(e.find("every axis needs as many values: 'phi' has 3, 'e' has 2"), std::string::npos)
      << e;
}

TEST(StudyCases, SweepTakesEachAxisAloneAndCasesFollowTheAxes) {
  const auto cases = expand_cases(spec("mode = \"sweep\"\n" + kTwoAxes +
                                       "[[case]]\nname = \"extra\"\nset = [\"scene.seed=3\"]\n"));
  EXPECT_EQ(names(cases), (std::vector<std::string>{"phi-0.05", "phi-0.1", "phi-0.2", "e-0.5",
                                                    "e-0.9", "extra"}));
  EXPECT_EQ(cases[3].axis_value, (std::vector<int>{-1, 0}));
  EXPECT_EQ(cases[5].axis_value, (std::vector<int>{-1, -1}));
  EXPECT_EQ(cases[5].overrides, std::vector<std::string>{"scene.seed=3"});
}

TEST(StudyCases, DuplicateNamesAndSharedKeysAreRefused) {
  const std::string same = error_of(spec(R"(
[[axis]]
name = "phi"
key = "inflow.area_fraction"
values = [0.1, 0.10]
)"));
  EXPECT_NE(same.find("both named 'phi-0.1'"), std::string::npos) << same;
  const std::string shared = error_of(spec(R"(
[[axis]]
name = "a"
key = "inflow.mach"
values = [3.0]
[[axis]]
name = "b"
values = [{ label = "x", inflow.mach = 4.0 }]
)"));
  EXPECT_NE(shared.find("axes 'a' and 'b' both set 'inflow.mach'"), std::string::npos) << shared;
  const std::string too_many = error_of(spec(
      "[[axis]]\nname = \"a\"\nkey = \"k\"\nvalues = [" +
      [] {
        std::string v;
        for (int k = 0; k < 101; ++k) v += (k ? ", " : "") + std::to_string(k);
        return v;
      }() +
      "]\n[[axis]]\nname = \"b\"\nkey = \"j\"\nvalues = [" +
      [] {
        std::string v;
        for (int k = 0; k < 100; ++k) v += (k ? ", " : "") + std::to_string(k);
        return v;
      }() +
      "]\n"));
  EXPECT_NE(too_many.find("10100 cases, more than the 10000"), std::string::npos) << too_many;
}

// The plan loads every case with the scene's own reader: a bad value in the last case is
// found before anything runs, and the scene a case resolves to is the one `granshock run`
// gets from the same overrides.
TEST(StudyPlan, FindsABadValueInTheLastCaseAndResolvesWhatTheRunResolves) {
  TempDir tmp;
  const auto base = tmp.write("small.toml", small_scene(true));
  const StudySpec good = spec(kTwoAxes, base.string());
  const StudyPlan plan = plan_study(good, tmp.path() / "out");
  ASSERT_EQ(plan.cases.size(), 6u);
  for (const PlannedCase& c : plan.cases) {
    EXPECT_EQ(c.dir, tmp.path() / "out" / c.spec.name);
    EXPECT_EQ(c.scene.name, c.spec.name);
    EXPECT_EQ(load_scene_file(base, run_overrides(good, c)).resolved, c.resolved) << c.spec.name;
  }
  try {
    plan_study(spec(kTwoAxes + "[[case]]\nname = \"last\"\nset = [\"inflow.area_fraction=0.69\"]\n",
                    base.string()),
               tmp.path() / "out");
    FAIL() << "a value the scene refuses must end the plan";
  } catch (const UserError& e) {
    EXPECT_NE(
        std::string(e.what()).find("case 'last' (--case 6): scene key 'inflow.area_fraction'"),
        std::string::npos)
        << e.what();
  }
}

TEST(StudyPlan, RefusesTwoCasesOfTheSameScene) {
  TempDir tmp;
  const auto base = tmp.write("small.toml", small_scene(true));
  try {
    plan_study(spec("[[case]]\nname = \"a\"\n[[case]]\nname = \"b\"\nset = [\"scene.seed=7\"]\n",
                    base.string()),
               tmp.path() / "out");
    FAIL() << "scene.seed = 7 is the small scene's own seed: both cases are the same scene";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("cases 'a' and 'b' resolve to the same scene"),
              std::string::npos)
        << e.what();
  }
}

TEST(StudyPlan, SweepValuesAtTheBasePointBecomeOneBaseCase) {
  TempDir tmp;
  const auto base = tmp.write("small.toml", small_scene(true));  // phi 0.1, e 0.5
  const StudySpec s = spec("mode = \"sweep\"\n" + kTwoAxes, base.string());
  const StudyPlan plan = plan_study(s, tmp.path() / "out");
  std::vector<std::string> got;
  for (const PlannedCase& c : plan.cases) got.push_back(c.spec.name);
  EXPECT_EQ(got, (std::vector<std::string>{"phi-0.05", "base", "phi-0.2", "e-0.9"}));
  EXPECT_EQ(plan.cases[1].spec.axis_value, (std::vector<int>{1, 0}))
      << "the base case carries phi = 0.1 and e = 0.5";
  EXPECT_TRUE(plan.cases[1].spec.overrides.empty());
  for (std::size_t k = 0; k < plan.cases.size(); ++k) EXPECT_EQ(plan.cases[k].spec.index, int(k));
}

// A case name that TOML would read as a number or a boolean stays the scene's name.
TEST(StudyPlan, NumericCaseNamesReachTheRunAsNames) {
  TempDir tmp;
  const auto base = tmp.write("small.toml", small_scene(true));
  const StudySpec s = spec(
      "[[case]]\nname = \"10\"\n[[case]]\nname = \"true\"\nset = "
      "[\"scene.seed=3\"]\n",
      base.string());
  const StudyPlan plan = plan_study(s, tmp.path() / "out");
  for (const PlannedCase& c : plan.cases) {
    const LoadedScene run = load_scene_file(base, run_overrides(s, c));
    EXPECT_EQ(run.scene.name, c.spec.name);
    EXPECT_EQ(run.resolved, c.resolved);
  }
}

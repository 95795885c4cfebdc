// The shipped studies (studies/): the paper's nine cases reproduce the scenes/paper/ files
// exactly, and the future-work study plans its one-dimensional sweeps around one base case.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "cases/study/study_plan.hpp"
#include "io/scene_file.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = GRANSHOCK_SOURCE_DIR;

StudyPlan plan_of(const std::string& study) {
  return plan_study(load_study_file(kSource / "studies" / study), "/nonexistent/out");
}

}  // namespace

// Every case of studies/paper.toml resolves to the scene of the scenes/paper/ file of the
// same name (scene.name aside: the study names its cases), and every file has its case.
TEST(ShippedStudies, PaperCasesAreTheScenesOfScenesPaper) {
  const StudyPlan plan = plan_of("paper.toml");
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(kSource / "scenes" / "paper"))
    if (entry.path().extension() == ".toml") files.insert(entry.path().stem().string());
  ASSERT_EQ(files.size(), 9u);
  ASSERT_EQ(plan.cases.size(), 9u);
  std::set<std::string> cases;
  for (const PlannedCase& c : plan.cases) {
    cases.insert(c.spec.name);
    const fs::path file = kSource / "scenes" / "paper" / (c.spec.name + ".toml");
    ASSERT_TRUE(fs::exists(file)) << "no scenes/paper file for case " << c.spec.name;
    const LoadedScene paper = load_scene_file(file, {"scene.name=" + c.spec.name});
    EXPECT_EQ(c.resolved, paper.resolved) << c.spec.name << " differs in: " << [&] {
      std::string keys;
      for (const auto& k : differing_keys(c.resolved, paper.resolved)) keys += k + " ";
      return keys;
    }();
  }
  EXPECT_EQ(cases, files);
}

TEST(ShippedStudies, FutureWorkSweepsFourDirectionsAroundOneBaseCase) {
  const StudyPlan plan = plan_of("future_work.toml");
  EXPECT_EQ(plan.spec.mode, StudyMode::sweep);
  ASSERT_EQ(plan.spec.axes.size(), 5u);
  int base = 0;
  for (const PlannedCase& c : plan.cases) {
    if (c.spec.name != "base") continue;
    ++base;
    for (int v : c.spec.axis_value) EXPECT_GE(v, 0) << "the base point lies on every axis";
  }
  EXPECT_EQ(base, 1);
  EXPECT_EQ(plan.cases.size(), 15u);
  for (const PlannedCase& c : plan.cases) {
    if (c.spec.name == "xsteel-0" || c.spec.name == "xsteel-1") {
      ASSERT_EQ(c.scene.setup.species.size(), 1u) << c.spec.name;
      EXPECT_EQ(c.scene.setup.species[0].material.name,
                c.spec.name == "xsteel-1" ? "steel" : "aluminium");
    }
    if (c.spec.name == "steel-glass") {
      ASSERT_EQ(c.scene.setup.species.size(), 2u);
      EXPECT_EQ(c.scene.setup.species[1].material.name, "glass");
      EXPECT_EQ(c.scene.setup.species[1].material.density_kg_m3, 2500.0);
    }
  }
}

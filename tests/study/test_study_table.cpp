// The study table and the states of case directories (docs/study.md, "The study table",
// "Skip and resume"), on run directories written by hand: what makes a case finished, how
// summary.json is flattened, and that an unfinished case keeps its row.
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <thread>

#include "cases/study/case_directory.hpp"
#include "cases/study/study_directory.hpp"
#include "cases/study/study_table.hpp"
#include "core/user_error.hpp"
#include "io/run_directory.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A run directory: the marker, and summary.json when `summary` is not empty.
void run_directory(const fs::path& dir, const std::string& summary) {
  write(dir / kRunMarker, "format = 1\n");
  if (!summary.empty()) write(dir / "summary.json", summary);
}

const char* kFinished = R"({"completed": true, "steps": 100, "wall_seconds": 2.5,
  "fields_bins": 40, "delta_over_D": null, "delta_over_D_reason": "no front",
  "inflow": {"requested": 10.5, "falls_short": false}, "variant": "2d/double",
  "inflow_calibration": {"iterations": [{"sigma": 1}]}, "inflow_warning": null})";

}  // namespace

TEST(CaseDirectory, StateComesFromTheRunsOwnFiles) {
  TempDir tmp;
  EXPECT_EQ(inspect_case_directory(tmp.path() / "absent").state, CaseState::missing);
  fs::create_directories(tmp.path() / "empty");
  EXPECT_EQ(inspect_case_directory(tmp.path() / "empty").state, CaseState::missing);

  run_directory(tmp.path() / "done", kFinished);
  const CaseDirectory done = inspect_case_directory(tmp.path() / "done");
  EXPECT_EQ(done.state, CaseState::finished);
  EXPECT_EQ(done.steps_done, 100);
  EXPECT_EQ(done.wall_seconds, 2.5);

  run_directory(tmp.path() / "no_fields", R"({"completed": true, "steps": 100})");
  EXPECT_EQ(inspect_case_directory(tmp.path() / "no_fields").state, CaseState::needs_fields);

  run_directory(tmp.path() / "stopped", R"({"completed": false, "steps": 40})");
  EXPECT_EQ(inspect_case_directory(tmp.path() / "stopped").state, CaseState::restartable)
      << "without checkpoint.h5 and run.h5 there is nothing to resume";
  write(tmp.path() / "stopped" / "checkpoint.h5", "x");
  write(tmp.path() / "stopped" / "run.h5", "x");
  const CaseDirectory stopped = inspect_case_directory(tmp.path() / "stopped");
  EXPECT_EQ(stopped.state, CaseState::resumable);
  EXPECT_EQ(stopped.steps_done, 40);

  run_directory(tmp.path() / "garbled", "{\"completed\": tru");
  write(tmp.path() / "garbled" / "checkpoint.h5", "x");
  write(tmp.path() / "garbled" / "run.h5", "x");
  EXPECT_EQ(inspect_case_directory(tmp.path() / "garbled").state, CaseState::resumable);
}

TEST(StudyTable, FlattensNumbersBooleansNullsAndReasonsButNotArraysOrOtherStrings) {
  nlohmann::ordered_json row;
  flatten_summary(nlohmann::json::parse(kFinished), "", row);
  EXPECT_EQ(row["inflow.requested"], 10.5);
  EXPECT_EQ(row["inflow.falls_short"], false);
  EXPECT_TRUE(row.contains("delta_over_D"));
  EXPECT_TRUE(row["delta_over_D"].is_null());
  EXPECT_EQ(row["delta_over_D_reason"], "no front");
  EXPECT_TRUE(row.contains("inflow_warning"));
  EXPECT_FALSE(row.contains("variant")) << "strings other than reasons and warnings";
  EXPECT_FALSE(row.contains("inflow_calibration.iterations")) << "arrays";
}

TEST(StudyTable, OneRowPerCaseWithStatusAxesSceneAndSummary) {
  TempDir tmp;
  const auto base = tmp.write("small.toml", small_scene(true));
  const StudySpec spec = parse_study("[study]\nname = \"t\"\nbase = \"" + base.string() + R"("
[[axis]]
name = "phi"
key = "inflow.area_fraction"
values = [0.05, 0.2]
[[axis]]
name = "U"
values = [{ label = "slow", inflow.velocity = 0.5 }]
[[case]]
name = "extra"
set = ["contact.restitution=0.8"]
)",
                                     "t.toml");
  const StudyPlan plan = plan_study(spec, tmp.path() / "out");
  run_directory(plan.cases[0].dir, kFinished);
  run_directory(plan.cases[1].dir, R"({"completed": false, "steps": 40})");
  const StudyTable t = study_table(plan, {{2, "the run failed numerically: boom"}});
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0]["status"], "finished");
  EXPECT_EQ(t.rows[1]["status"], "unfinished");
  EXPECT_EQ(t.rows[2]["status"], "failed");
  EXPECT_EQ(t.rows[2]["error"], "the run failed numerically: boom");
  EXPECT_EQ(t.rows[0]["axis.phi"], 0.05);
  EXPECT_EQ(t.rows[0]["axis.U"], "slow");
  EXPECT_TRUE(t.rows[2]["axis.phi"].is_null()) << "a [[case]] entry has no axis value";
  EXPECT_EQ(t.rows[0]["scene.U"], 0.5);
  EXPECT_EQ(t.rows[0]["scene.phi_inf"], 0.05);
  EXPECT_EQ(t.rows[0]["scene.D_over_d"], 10.0);
  EXPECT_EQ(t.rows[2]["scene.restitution"], 0.8);
  EXPECT_EQ(t.rows[0]["scene.number_fraction.steel"], 0.5);
  EXPECT_EQ(t.rows[0]["wall_seconds"], 2.5);
  EXPECT_EQ(t.rows[0]["inflow.requested"], 10.5);
  EXPECT_TRUE(t.rows[1]["inflow.requested"].is_null()) << "only finished cases give results";
  for (const auto& row : t.rows) EXPECT_EQ(row.size(), t.columns.size());
  const std::vector<std::string> lead = {"case",         "index",    "status", "source",
                                         "wall_seconds", "axis.phi", "axis.U"};
  EXPECT_EQ(std::vector<std::string>(t.columns.begin(), t.columns.begin() + 7), lead);
  EXPECT_EQ(t.rows[0]["source"], "run");
  EXPECT_TRUE(t.rows[1]["source"].is_null()) << "a case that is not finished has no source";

  write_study_table(tmp.path(), t);
  const std::string csv = read(tmp.path() / "study.csv");
  std::istringstream lines(csv);
  std::string header, first;
  std::getline(lines, header);
  std::getline(lines, first);
  EXPECT_EQ(header.rfind("case,index,status,source,wall_seconds,axis.phi,axis.U,scene.", 0), 0u)
      << header;
  EXPECT_EQ(first.rfind("\"phi-0.05_slow\",0,\"finished\",\"run\",2.5,0.05,\"slow\",", 0), 0u)
      << first;
  EXPECT_NE(csv.find(",\"no front\""), std::string::npos);
  const auto json = nlohmann::json::parse(read(tmp.path() / "study.json"));
  ASSERT_EQ(json.size(), 3u);
  EXPECT_TRUE(json[0]["delta_over_D"].is_null());
  EXPECT_EQ(json[1]["status"], "unfinished");
}

TEST(StudyDirectory, IsReusedOnlyByItsOwnStudy) {
  TempDir tmp;
  const fs::path out = tmp.path() / "study";
  EXPECT_EQ(check_study_directory(out, "a"), StudyDirectoryState::absent);
  claim_study_directory(out, "a");
  EXPECT_EQ(check_study_directory(out, "a"), StudyDirectoryState::this_study);
  claim_study_directory(out, "a");  // again: the same study
  EXPECT_THROW(check_study_directory(out, "b"), UserError);
  EXPECT_THROW(claim_study_directory(out, "b"), UserError);
  write(tmp.path() / "mine" / "notes.txt", "a user's file");
  EXPECT_THROW(check_study_directory(tmp.path() / "mine", "a"), UserError);
  EXPECT_EQ(read(tmp.path() / "mine" / "notes.txt"), "a user's file");
  write(tmp.path() / "file", "x");
  EXPECT_THROW(check_study_directory(tmp.path() / "file", "a"), UserError);
}

// Slurm array tasks (or `--case` runs started together) look at the study directory while
// another task claims it and makes its first case directory: a look must see an empty
// directory or this study, never "not empty and holds no study". Once seen with two
// `--case` runs started in the same second; the look listed the directory after the
// other task's marker appeared but had checked for the marker before.
TEST(StudyDirectory, ALookWhileAnotherTaskClaimsSeesEmptyOrThisStudy) {
  TempDir tmp;
  int refused = 0;
  for (int trial = 0; trial < 400 && refused == 0; ++trial) {
    const fs::path out = tmp.path() / ("study" + std::to_string(trial));
    std::atomic<bool> go{false};
    std::thread claimer([&] {
      while (!go) {
      }
      claim_study_directory(out, "a");
      fs::create_directory(out / "case-0");
    });
    go = true;
    for (int look = 0; look < 200; ++look) {
      try {
        check_study_directory(out, "a");
      } catch (const UserError&) {
        ++refused;
        break;
      }
    }
    claimer.join();
  }
  EXPECT_EQ(refused, 0);
}

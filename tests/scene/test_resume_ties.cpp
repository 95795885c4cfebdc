// A resume joins checkpoint.h5 and run.h5 only when the checkpoint was written with that
// run.h5 (docs/output_format.md, "What a resume checks"): a final checkpoint copied into a
// half-finished directory, an older run.h5 copied back, another run's run.h5 are refused
// with one line and change nothing. And an error that is not a failed write (the field
// analysis without its Python) does not send the user to make room and resume.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/run_file.hpp"
#include "run_helpers.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::run_options;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// The small scene cut to 20 000 steps: snapshots at 0, 12 500 and 20 000, time-series rows
// every 2 500 steps, checkpoints at 0 and 20 000 (and wherever a run is stopped).
const std::vector<std::string> kShort = {"time.duration=0.004", "time.production_start=0.002"};

struct Runs {
  TempDir tmp;
  fs::path scene = tmp.write("small.toml", small_scene(true));

  RunOptions options(const std::string& dir, long stop_after = 0, bool resume = false) const {
    RunOptions o = run_options(scene, tmp.path() / dir, kShort);
    o.stop_after_steps = stop_after;
    o.resume = resume;
    return o;
  }
  fs::path dir(const std::string& name) const { return tmp.path() / name; }
};

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The resume's refusal (empty if it was accepted), and that it changed nothing.
std::string refused_resume(const Runs& runs, const std::string& dir) {
  const std::string run_before = bytes_of(runs.dir(dir) / "run.h5");
  const std::string checkpoint_before = bytes_of(runs.dir(dir) / "checkpoint.h5");
  std::string message;
  try {
    run_scene(runs.options(dir, 0, true));
  } catch (const UserError& e) {
    message = e.what();
  }
  EXPECT_EQ(bytes_of(runs.dir(dir) / "run.h5"), run_before) << "run.h5 changed";
  EXPECT_EQ(bytes_of(runs.dir(dir) / "checkpoint.h5"), checkpoint_before);
  EXPECT_FALSE(fs::exists(runs.dir(dir) / "summary.json.tmp"));
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  return message;
}

}  // namespace

TEST(ResumeTies, CheckpointRecordsTheRunFileItWasWrittenWith) {
  Runs runs;
  ASSERT_EQ(run_scene(runs.options("run", 5000)), 0);
  CheckpointExtras extras;
  static_cast<void>(read_checkpoint(runs.dir("run") / "checkpoint.h5", extras));
  const RunFileRecord file = RunFile::open_read_only(runs.dir("run") / "run.h5").record();
  EXPECT_EQ(extras.run_id, file.run_id);
  EXPECT_EQ(extras.run_id.size(), 32u);
  EXPECT_EQ(extras.run_frames, 1);  // step 0
  EXPECT_EQ(extras.run_rows, 3);    // steps 0, 2 500, 5 000
  EXPECT_EQ(file.frames, 1);
  EXPECT_EQ(file.rows, 3);
}

TEST(ResumeTies, AFinalCheckpointCopiedIntoAHalfFinishedDirectoryIsRefused) {
  Runs runs;
  ASSERT_EQ(run_scene(runs.options("run", 10000)), 0);
  fs::copy(runs.dir("run"), runs.dir("half"), fs::copy_options::recursive);
  ASSERT_EQ(run_scene(runs.options("run", 0, true)), 0);  // to the end: step 20 000
  fs::copy_file(runs.dir("run") / "checkpoint.h5", runs.dir("half") / "checkpoint.h5",
                fs::copy_options::overwrite_existing);
  fs::remove(runs.dir("half") / "summary.json");
  const std::string message = refused_resume(runs, "half");
  EXPECT_NE(message.find("holds 1 snapshot and 5 time-series rows up to step 20000 (its last at "
                         "step 10000), but the checkpoint.h5 beside it (step 20000) was written "
                         "when it held 3 and 9"),
            std::string::npos)
      << message;
  EXPECT_FALSE(fs::exists(runs.dir("half") / "summary.json")) << "the run was completed";
}

TEST(ResumeTies, AnOlderRunFileCopiedBackIsRefused) {
  Runs runs;
  ASSERT_EQ(run_scene(runs.options("run", 5000)), 0);
  fs::copy_file(runs.dir("run") / "run.h5", runs.dir("old.h5"));
  ASSERT_EQ(run_scene(runs.options("run", 10000, true)), 0);  // to step 15 000, past a frame
  fs::copy_file(runs.dir("old.h5"), runs.dir("run") / "run.h5",
                fs::copy_options::overwrite_existing);
  const std::string message = refused_resume(runs, "run");
  EXPECT_NE(message.find("holds 1 snapshot and 3 time-series rows up to step 15000"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("(step 15000) was written when it held 2 and 7"), std::string::npos)
      << message;
}

TEST(ResumeTies, AnotherRunsRunFileIsRefused) {
  Runs runs;
  ASSERT_EQ(run_scene(runs.options("run", 5000)), 0);
  ASSERT_EQ(run_scene(runs.options("other", 5000)), 0);  // the same scene, another run
  fs::copy_file(runs.dir("other") / "run.h5", runs.dir("run") / "run.h5",
                fs::copy_options::overwrite_existing);
  const std::string message = refused_resume(runs, "run");
  EXPECT_NE(message.find("belongs to another run than the checkpoint.h5 beside it"),
            std::string::npos)
      << message;
}

// Not a failed write: nothing to make room for, and the run's data is complete.
TEST(RunErrors, AFailedAnalysisSaysTheDataIsCompleteNotMakeRoom) {
  Runs runs;
  const char* saved = std::getenv("GRANSHOCK_PYTHON");
  const std::string old = saved != nullptr ? saved : "";
  setenv("GRANSHOCK_PYTHON", "/nonexistent/python3", 1);
  std::string message;
  RunOptions o = runs.options("run");
  o.figures = true;  // the analysis fails where it starts Python for the figures
  try {
    run_scene(o);
  } catch (const UserError& e) {
    message = e.what();
  }
  if (saved != nullptr)
    setenv("GRANSHOCK_PYTHON", old.c_str(), 1);
  else
    unsetenv("GRANSHOCK_PYTHON");
  EXPECT_NE(message.find("no Python interpreter at /nonexistent/python3"), std::string::npos)
      << message;
  EXPECT_EQ(message.find("make room"), std::string::npos) << message;
  EXPECT_EQ(message.find("--resume"), std::string::npos) << message;
  EXPECT_NE(message.find("the run's data is complete"), std::string::npos) << message;
  EXPECT_NE(message.find("`granshock fields " + runs.dir("run").string() + "` redoes"),
            std::string::npos)
      << message;
  EXPECT_TRUE(fs::exists(runs.dir("run") / "summary.json"));
}

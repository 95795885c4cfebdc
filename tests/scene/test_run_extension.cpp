// A resume that lengthens the run or moves its production window (docs/scene_format.md,
// "Extending a run"): the extended run equals an uninterrupted run of the longer scene
// bit for bit, and every change that could not continue it is refused in one line, the
// run directory left as it was.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/marked_directory.hpp"
#include "io/run_file.hpp"
#include "kernels/sampling/bin_accumulator.hpp"
#include "run_helpers.hpp"
#include "scene_fixtures.hpp"
#include "stopped_run.hpp"

using namespace granshock;
using granshock::testing::read_json;
using granshock::testing::run_options;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// dt = 2e-7 s: 0.004 s is step 20 000, 0.006 s step 30 000; a sample every 100 steps
// (output.sample_every), checkpoints at the end of a run this short.
const std::vector<std::string> kShort = {"time.duration=0.004", "time.production_start=0.002"};
const std::vector<std::string> kLong = {"time.duration=0.006", "time.production_start=0.002"};

std::vector<double> series(const RunFile& f, const std::string& name) {
  return f.read_array("/observables/" + name + "/value");
}

// Without figures: the tests compare data, and drawing takes longer than the runs.
RunOptions quick(RunOptions o) {
  o.figures = false;
  return o;
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Whether this build samples by row owners, whose sums are bitwise the same for any
// thread count; atomics (device paths, or more than 16 threads) sum to round-off
// (docs/fields.md, "Cost of sampling").
bool sums_are_bitwise() {
  using Space = Kokkos::DefaultExecutionSpace;
  return BinAccumulator<Space, DefaultPaths<Space>>::resolve(ScatterStrategy::automatic) ==
         ScatterStrategy::rows;
}

void expect_same_sums(const std::vector<double>& a, const std::vector<double>& b,
                      const char* what) {
  if (sums_are_bitwise())
    EXPECT_EQ(a, b) << what << " differ";
  else
    EXPECT_TRUE(granshock::testing::same_sums(a, b)) << what << " differ beyond round-off";
}

// The end states of two runs: particles bit for bit, field sums bit for bit where the
// sampling is (sums_are_bitwise), to round-off where it takes atomics.
void expect_same_end(const fs::path& straight, const fs::path& extended) {
  CheckpointExtras ea, eb;
  const SolverState a = read_checkpoint(straight / "checkpoint.h5", ea);
  const SolverState b = read_checkpoint(extended / "checkpoint.h5", eb);
  EXPECT_EQ(a.step, 30000);
  EXPECT_EQ(b.step, a.step);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.position, b.position) << "positions differ: the extended run is not bitwise equal";
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.force, b.force);
  EXPECT_EQ(ea.inserted, eb.inserted);
  EXPECT_EQ(ea.deleted_outlet, eb.deleted_outlet);
  EXPECT_EQ(ea.bin_shape, eb.bin_shape);
  expect_same_sums(ea.bin_sums, eb.bin_sums, "the field sums (and samples per block)");
  EXPECT_EQ(ea.scene_resolved, eb.scene_resolved);
  // What the analysis reads: the scene and the sums in run.h5.
  const RunFile fa = RunFile::open_read_only(straight / "run.h5");
  const RunFile fb = RunFile::open_read_only(extended / "run.h5");
  EXPECT_EQ(fa.scene_resolved(), fb.scene_resolved());
  expect_same_sums(fa.read_array("/fields/grid/sums"), fb.read_array("/fields/grid/sums"),
                   "run.h5's grid sums");
  EXPECT_EQ(fa.read_array("/fields/grid/samples"), fb.read_array("/fields/grid/samples"));
  for (const char* name : {"particles", "kinetic_energy", "temperature", "contacts", "inserted"})
    EXPECT_EQ(series(fa, name), series(fb, name)) << name;
  EXPECT_EQ(read_json(straight / "summary.json")["steps"], 30000);
  EXPECT_EQ(read_json(extended / "summary.json")["steps"], 30000);
}

}  // namespace

// Stopped inside the first block of the window (step 10 500; blocks of 1000 steps to
// 0.004 s, of 2000 to 0.006 s): its six samples lie in block 0 of either window, so the
// sums go on from the checkpoint.
TEST(RunResumeExtended, InsideTheWindowEqualsTheLongerRunBitwise) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  ASSERT_EQ(run_scene(quick(run_options(scene, tmp.path() / "straight", kLong))), 0);
  RunOptions first = quick(run_options(scene, tmp.path() / "extended", kShort));
  first.stop_after_steps = 10500;
  ASSERT_EQ(run_scene(first), 0);
  RunOptions second = quick(run_options(scene, tmp.path() / "extended", kLong));
  second.resume = true;
  ASSERT_EQ(run_scene(second), 0);

  expect_same_end(tmp.path() / "straight", tmp.path() / "extended");
  const RunFile fa = RunFile::open_read_only(tmp.path() / "straight" / "run.h5");
  const RunFile fb = RunFile::open_read_only(tmp.path() / "extended" / "run.h5");
  EXPECT_EQ(fa.frames().size(), fb.frames().size());
  // The history: one extension, at the checkpoint's step, nothing dropped.
  std::vector<long> shape;
  const std::vector<double> rows = fb.read_array("/scene/extensions", &shape);
  ASSERT_EQ(shape, (std::vector<long>{1, 7}));
  EXPECT_EQ(rows, (std::vector<double>{10500, 10500 * 2e-7, 0.004, 0.006, 0.002, 0.002, 0}));
  EXPECT_FALSE(fa.has("/scene/extensions"));
  const nlohmann::json summary = read_json(tmp.path() / "extended" / "summary.json");
  ASSERT_EQ(summary["extensions"].size(), 1u);
  EXPECT_EQ(summary["extensions"][0]["duration_after"], 0.006);
  EXPECT_GT(summary["particle_steps_per_second"].get<double>(), 0);
}

// A finished run continued with a new production window from its end (0.004 s): the
// earlier window's sums are dropped, the sample at step 20 000 (the earlier end, which that
// window does not sample) is taken, and the run equals one whose window starts there.
TEST(RunResumeExtended, FinishedRunWithANewWindowEqualsTheLongerRunBitwise) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const std::vector<std::string> later = {"time.duration=0.006", "time.production_start=0.004"};
  ASSERT_EQ(run_scene(quick(run_options(scene, tmp.path() / "straight", later))), 0);
  ASSERT_EQ(run_scene(quick(run_options(scene, tmp.path() / "extended", kShort))), 0);
  ASSERT_EQ(read_json(tmp.path() / "extended" / "summary.json")["completed"], true);
  RunOptions second = quick(run_options(scene, tmp.path() / "extended", later));
  second.resume = true;
  ASSERT_EQ(run_scene(second), 0);

  expect_same_end(tmp.path() / "straight", tmp.path() / "extended");
  const RunFile fa = RunFile::open_read_only(tmp.path() / "straight" / "run.h5");
  const RunFile fb = RunFile::open_read_only(tmp.path() / "extended" / "run.h5");
  // Time-series rows every 2500 steps in both (compared in expect_same_end); the first
  // leg's end (step 20 000) is one of them.
  // Snapshots every 12 500 steps and at the end: the first leg's end wrote one more, at
  // step 20 000, which run.h5 keeps (docs/output_format.md, "Extending a run").
  std::vector<long> steps_a, steps_b;
  for (const SnapshotFrame& f : fa.frames()) steps_a.push_back(f.step);
  for (const SnapshotFrame& f : fb.frames()) steps_b.push_back(f.step);
  EXPECT_EQ(steps_a, (std::vector<long>{0, 12500, 25000, 30000}));
  EXPECT_EQ(steps_b, (std::vector<long>{0, 12500, 20000, 25000, 30000}));
  const std::vector<double> rows = fb.read_array("/scene/extensions");
  EXPECT_EQ(rows, (std::vector<double>{20000, 0.004, 0.004, 0.006, 0.002, 0.004, 100}));
  EXPECT_EQ(read_json(tmp.path() / "extended" / "summary.json")["completed"], true);
}

struct BadExtension {
  const char* name;
  std::vector<std::string> sets;
  const char* expected;
};

class RunResumeRefusesChange : public ::testing::TestWithParam<BadExtension> {};

// After a finished run to 0.004 s (production from 0.002 s): each change is refused in one
// line naming the key, and the directory stays as it was.
TEST_P(RunResumeRefusesChange, InOneLineLeavingTheRunAsItWas) {
  static TempDir tmp;  // one finished run for every case
  static const fs::path scene = tmp.write("small.toml", small_scene(true));
  static const fs::path dir = tmp.path() / "run";
  if (!fs::exists(dir / "summary.json")) {
    ASSERT_EQ(run_scene(quick(run_options(scene, dir, kShort))), 0);
  }
  const std::string checkpoint = file_text(dir / "checkpoint.h5");
  const std::string run_h5 = file_text(dir / "run.h5");
  const std::string log = file_text(dir / "log.txt");
  const std::string marker = file_text(dir / kRunMarker);
  RunOptions o = quick(run_options(scene, dir, GetParam().sets));
  o.resume = true;
  try {
    run_scene(o);
    FAIL() << "accepted";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(GetParam().expected), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_EQ(file_text(dir / "checkpoint.h5"), checkpoint);
  EXPECT_EQ(file_text(dir / "run.h5"), run_h5);
  EXPECT_EQ(file_text(dir / "log.txt"), log);
  // The marker too: a refused resume once rewrote it (the claim came before the checks).
  EXPECT_EQ(file_text(dir / kRunMarker), marker);
}

INSTANTIATE_TEST_SUITE_P(
    Changes, RunResumeRefusesChange,
    ::testing::Values(
        BadExtension{
            "other_key",
            {"time.duration=0.006", "time.production_start=0.002", "contact.restitution=0.6"},
            "contact.restitution differ from the run in"},
        BadExtension{"shorter",
                     {"time.duration=0.003", "time.production_start=0.001"},
                     "'time.duration' = 0.003 s (was 0.004 s) ends by the checkpoint at t = "
                     "0.004 s"},
        // The 100 samples fill ten blocks of 1000 steps; to 0.006 s the blocks are 2000.
        BadExtension{"blocks_cut_elsewhere", kLong,
                     "'time.duration' = 0.006 s (was 0.004 s): the 100 field samples taken by "
                     "the checkpoint at t = 0.004 s lie in the output.blocks = 10 blocks"},
        // A window from 0.003 s would hold 50 samples, not the checkpoint's 100.
        BadExtension{"window_start_inside_the_samples",
                     {"time.duration=0.006", "time.production_start=0.003"},
                     "'time.production_start' = 0.003 s (was 0.002 s): the checkpoint at t = "
                     "0.004 s holds the 100 field samples"},
        // Values that differ are written so that they differ ("0.004 s (was 0.004 s)").
        BadExtension{"longer_by_less_than_a_step",
                     {"time.duration=0.00400000001", "time.production_start=0.002"},
                     "'time.duration' = 0.00400000001 s (was 0.004 s) ends by the checkpoint"},
        // An empty window names time.duration, which the resume changed, first.
        BadExtension{"window_empty",
                     {"time.duration=0.0001", "time.production_start=0.002"},
                     "scene keys 'time.duration' = 0.0001 s and 'time.production_start' = "
                     "0.002 s: the production window [production_start, duration) is empty"},
        BadExtension{"window_start_earlier",
                     {"time.duration=0.006", "time.production_start=0.001"},
                     "'time.production_start' = 0.001 s (was 0.002 s)"}),
    [](const ::testing::TestParamInfo<BadExtension>& p) { return p.param.name; });

// The program: exit code 2 and one line on stderr.
TEST(RunResumeExtended, ProgramRefusesAShorterRunInOneLine) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path dir = tmp.path() / "run";
  RunOptions first = quick(run_options(scene, dir, kShort));
  first.stop_after_steps = 12000;
  ASSERT_EQ(run_scene(first), 0);
  const std::string cmd = "'" GRANSHOCK_PROGRAM "' run '" + scene.string() + "' --out '" +
                          dir.string() +
                          "' --resume --quiet --set time.duration=0.0022 --set "
                          "time.production_start=0.0002 >/dev/null 2>'" +
                          (tmp.path() / "err.txt").string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream err(tmp.path() / "err.txt");
  std::vector<std::string> lines;
  for (std::string line; std::getline(err, line);)
    if (line.rfind("Kokkos::", 0) != 0 && line.rfind("  ", 0) != 0) lines.push_back(line);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("granshock: error: --resume: scene key 'time.duration' = 0.0022 s", 0),
            0u)
      << lines[0];
}

// --resume forgot the run's own --set: a run to 0.004 s (its --set) stopped and resumed
// without it ran to the scene file's 0.01 s, and repeating the --set was then refused. The
// checkpoint keeps every leg's --set, and a resume applies them before its own.
TEST(RunResumeKeeps, TheRunsOwnSetOverrides) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  ASSERT_EQ(run_scene(quick(run_options(scene, tmp.path() / "straight", kShort))), 0);
  RunOptions first = quick(run_options(scene, tmp.path() / "resumed", kShort));
  first.stop_after_steps = 10500;
  ASSERT_EQ(run_scene(first), 0);
  RunOptions again = quick(run_options(scene, tmp.path() / "resumed"));  // no --set
  again.resume = true;
  ASSERT_EQ(run_scene(again), 0);
  CheckpointExtras ea, eb;
  const SolverState a = read_checkpoint(tmp.path() / "straight" / "checkpoint.h5", ea);
  const SolverState b = read_checkpoint(tmp.path() / "resumed" / "checkpoint.h5", eb);
  EXPECT_EQ(b.step, 20000) << "the resume ran the scene file's duration";
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(ea.scene_resolved, eb.scene_resolved);
  EXPECT_EQ(read_json(tmp.path() / "resumed" / "summary.json")["steps"], 20000);
  ASSERT_TRUE(eb.scene_overrides);
  EXPECT_EQ(*eb.scene_overrides, kShort);
  EXPECT_FALSE(RunFile::open_read_only(tmp.path() / "resumed" / "run.h5").has("/scene/extensions"))
      << "no extension: the scene is the run's own";
  // The same --set again is the same scene: accepted, nothing to extend.
  RunOptions repeated = quick(run_options(scene, tmp.path() / "resumed", kShort));
  repeated.resume = true;
  EXPECT_EQ(run_scene(repeated), 0);
  // A --set with --resume still changes it: a longer run from the kept scene.
  RunOptions longer = quick(run_options(scene, tmp.path() / "resumed", {"time.duration=0.006"}));
  longer.resume = true;
  const std::string why = [&] {
    try {
      run_scene(longer);
    } catch (const UserError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  }();
  // production_start stays the run's 0.002 s: the blocks of a window to 0.006 s cut
  // elsewhere, the refusal a run of kShort extended to 0.006 s meets (RunResumeRefusesChange).
  EXPECT_NE(why.find("'time.duration' = 0.006 s (was 0.004 s): the 100 field samples"),
            std::string::npos)
      << why;
}

// A --set with --resume that only the kept ones make valid: the run's production_start
// (0.002 s) before a new duration the file's own (0.005 s) would refuse as an empty window.
TEST(RunResumeKeeps, ASetThatOnlyTheKeptOnesMakeValid) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  RunOptions first = quick(run_options(scene, tmp.path() / "run", kShort));
  first.stop_after_steps = 10500;
  ASSERT_EQ(run_scene(first), 0);
  RunOptions inside = quick(run_options(scene, tmp.path() / "run", {"time.duration=0.0045"}));
  inside.resume = true;
  inside.dry_run = true;  // the checks alone: 0.0045 s cuts the blocks elsewhere when run
  ::testing::internal::CaptureStdout();
  EXPECT_EQ(run_scene(inside), 0);
  const std::string resolved = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(resolved.find("production_start = 0.002"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("duration = 0.0045"), std::string::npos) << resolved;
}

// The interrupt and --stop-after-steps messages name the command that continues the run.
TEST(RunResumeKeeps, TheStopMessageNamesTheCommand) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path dir = tmp.path() / "run";
  RunOptions first = quick(run_options(scene, dir, kShort));
  first.stop_after_steps = 1000;
  first.quiet = false;
  ::testing::internal::CaptureStderr();
  ASSERT_EQ(run_scene(first), 0);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("stopped after 1000 steps at step 1000; continue with --resume: granshock "
                     "run '" +
                     scene.string() + "' --out '" + dir.string() + "' --resume"),
            std::string::npos)
      << err;
}

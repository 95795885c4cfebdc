// The run directory belongs to the user unless granshock marked it (docs/output_format.md):
// --overwrite removes only what a run writes, only where granshock's marker is; an
// unmarked directory that is not empty is refused and left untouched; a running run
// holds a lock; --resume follows the same rules.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <thread>

#include "cases/bow_shock/run_command.hpp"
#include "core/user_error.hpp"
#include "io/run_directory.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// A very short run of the small scene (before its production window: no fields).
RunOptions short_run(const fs::path& scene, const fs::path& out) {
  RunOptions o;
  o.scene_file = scene;
  o.out_dir = out;
  o.overrides = {"time.duration=0.0004", "time.production_start=0.0002", "output.sample_every=10"};
  o.quiet = true;
  return o;
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Every entry below `dir` (not following links) with its content, or "->target" for links.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path rel = fs::relative(it->path(), dir);
    if (it->is_symlink())
      out[rel.string()] = "->" + fs::read_symlink(it->path()).string();
    else if (it->is_regular_file())
      out[rel.string()] = read(it->path());
    else
      out[rel.string()] = "(dir)";
  }
  return out;
}

std::string refusal(const RunOptions& o) {
  try {
    run_scene(o);
  } catch (const UserError& e) {
    return e.what();
  }
  return "(accepted)";
}

// Runs with the current directory set to `dir` for the scope of the object.
class InDirectory {
 public:
  explicit InDirectory(const fs::path& dir) : old_(fs::current_path()) { fs::current_path(dir); }
  ~InDirectory() { fs::current_path(old_); }

 private:
  fs::path old_;
};

}  // namespace

TEST(RunDirectoryRefuses, AnUnmarkedDirectoryThatIsNotEmptyAndLeavesItUntouched) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path user = tmp.path() / "user";
  write(user / "notes.txt", "my notes");
  write(user / "sub" / "data.csv", "1,2,3");
  fs::create_symlink(tmp.path() / "small.toml", user / "link.toml");
  const auto before = tree(user);
  for (const DirectoryMode mode :
       {DirectoryMode::create, DirectoryMode::overwrite, DirectoryMode::resume}) {
    RunOptions o = short_run(scene, user);
    o.overwrite = mode == DirectoryMode::overwrite;
    o.resume = mode == DirectoryMode::resume;
    const std::string why = refusal(o);
    EXPECT_NE(why.find("is not a granshock run directory"), std::string::npos) << why;
    EXPECT_EQ(why.find('\n'), std::string::npos) << "one line";
    EXPECT_EQ(tree(user), before) << "a refused run touched the user's directory";
  }
  EXPECT_EQ(read(tmp.path() / "small.toml"), small_scene(true)) << "the link's target changed";
}

TEST(RunDirectoryRefuses, TheCurrentDirectoryHoldingTheSceneFile) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  write(tmp.path() / "notes.txt", "mine");
  const auto before = tree(tmp.path());
  InDirectory here(tmp.path());
  for (bool overwrite : {false, true}) {
    RunOptions o = short_run("small.toml", ".");
    o.overwrite = overwrite;
    EXPECT_NE(refusal(o).find("is not a granshock run directory"), std::string::npos);
  }
  EXPECT_EQ(tree(tmp.path()), before);
}

TEST(RunDirectoryOverwrite, RemovesOnlyWhatARunWritesInEveryLayout) {
  TempDir tmp;
  const auto outside = tmp.write("outside.txt", "precious");
  const fs::path run = tmp.path() / "run";
  // An empty directory (here the current one) is claimed, and the scene file may live in
  // a directory that later becomes a run directory's parent or the run directory itself.
  fs::create_directories(run);
  const fs::path scene = run / "scene.toml";
  {
    InDirectory here(run);
    ASSERT_EQ(run_scene(short_run(tmp.write("small.toml", small_scene(true)), ".")), 0);
  }
  ASSERT_TRUE(fs::exists(run / kRunMarker));
  write(scene, small_scene(true));
  write(run / "notes.txt", "beside");
  write(run / "sub" / "data.csv", "in a subdirectory");
  write(run / "figures" / "mine.png", "a user's figure among granshock's");
  fs::create_symlink(outside, run / "link-to-outside.txt");
  fs::create_symlink(tmp.path(), run / "link-to-parent");
  const auto user_files = [&] {
    auto t = tree(run);
    std::map<std::string, std::string> mine;
    for (const char* name : {"scene.toml", "notes.txt", "sub", "sub/data.csv", "figures/mine.png",
                             "link-to-outside.txt", "link-to-parent"})
      mine[name] = t[name];
    return mine;
  };
  const auto before = user_files();

  RunOptions again = short_run(scene, run);
  again.overwrite = true;
  ASSERT_EQ(run_scene(again), 0);
  EXPECT_EQ(user_files(), before);
  EXPECT_EQ(read(outside), "precious");
  // And the parent of the scene file as --out: the run directory's own parent is not
  // marked, so it is refused.
  RunOptions parent = short_run(scene, tmp.path());
  parent.overwrite = true;
  EXPECT_NE(refusal(parent).find("is not a granshock run directory"), std::string::npos);
  EXPECT_EQ(read(outside), "precious");
}

TEST(RunDirectoryOverwrite, CleansAMarkedRunDirectoryCompletely) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  // A full run writes everything: fields, figures (whatever GRANSHOCK_FIGURES says), summary.
  RunOptions full = short_run(scene, run);
  full.overrides = {"time.duration=0.002", "time.production_start=0.001", "output.sample_every=10"};
  full.figures = true;
  ASSERT_EQ(run_scene(full), 0);
  ASSERT_TRUE(fs::exists(run / "fields.h5"));
  ASSERT_TRUE(fs::exists(run / "figures" / "mach.png"));
  // Nothing a run writes is missing from run_outputs(): otherwise --overwrite would leave
  // stale results behind.
  for (const auto& [name, content] : tree(run)) {
    if (name == kRunMarker || name == "figures") continue;
    EXPECT_NE(std::find(run_outputs().begin(), run_outputs().end(), name), run_outputs().end())
        << name << " is written by a run but not listed in run_outputs()";
  }
  // A stale temporary (a killed run) and a run stopped before its production window:
  // no file of the first run may survive.
  write(run / "checkpoint.h5.tmp", "half a checkpoint");
  RunOptions early = short_run(scene, run);
  early.overwrite = true;
  early.stop_after_steps = 100;
  ASSERT_EQ(run_scene(early), 0);
  for (const char* gone : {"fields.h5", "fields.xmf", "figures", "checkpoint.h5.tmp"})
    EXPECT_FALSE(fs::exists(run / gone)) << gone << " of the previous run survived --overwrite";
}

TEST(RunDirectoryRefuses, AMarkedDirectoryWithoutOverwriteOrResume) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  ASSERT_EQ(run_scene(short_run(scene, tmp.path() / "run")), 0);
  const std::string why = refusal(short_run(scene, tmp.path() / "run"));
  EXPECT_NE(why.find("already holds a granshock run"), std::string::npos) << why;
  EXPECT_NE(why.find("--overwrite"), std::string::npos) << why;
}

TEST(RunDirectoryRefuses, AnOutputNameThatIsASymbolicLink) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const auto outside = tmp.write("outside.h5", "not to be truncated");
  const fs::path run = tmp.path() / "run";
  ASSERT_EQ(run_scene(short_run(scene, run)), 0);
  fs::remove(run / "run.h5");
  fs::create_symlink(outside, run / "run.h5");
  RunOptions o = short_run(scene, run);
  o.overwrite = true;
  EXPECT_NE(refusal(o).find("is a symbolic link"), std::string::npos);
  EXPECT_EQ(read(outside), "not to be truncated");
}

TEST(RunDirectoryRefuses, ADirectoryInUseByAnotherRun) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  ASSERT_EQ(run_scene(short_run(scene, run)), 0);
  const auto before = tree(run);
  {
    // Another run holds the directory (its lock is per open file, so this process
    // stands for a second one).
    const RunDirectory other = RunDirectory::claim(run, DirectoryMode::resume);
    for (bool resume : {false, true}) {
      RunOptions o = short_run(scene, run);
      o.overwrite = !resume;
      o.resume = resume;
      const std::string why = refusal(o);
      EXPECT_NE(why.find("in use by another granshock run"), std::string::npos) << why;
    }
  }
  auto after = tree(run);
  after.erase(kRunMarker);  // the marker names the last claimant's pid
  auto expected = before;
  expected.erase(kRunMarker);
  EXPECT_EQ(after, expected);
  RunOptions o = short_run(scene, run);
  o.overwrite = true;
  EXPECT_EQ(run_scene(o), 0) << "the lock must be released with its holder";
}

TEST(RunDirectoryRefuses, ARunDirectoryOfAnotherFormatWithAClearMessage) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  ASSERT_EQ(run_scene(short_run(scene, run)), 0);
  write(run / kRunMarker, "granshock run directory\nformat = 99\nversion = 9.0.0\npid = 1\n");
  RunOptions o = short_run(scene, run);
  o.resume = true;
  const std::string why = refusal(o);
  EXPECT_NE(why.find("granshock 9.0.0 in run-directory format 99"), std::string::npos) << why;
}

TEST(RunDirectoryResume, RemovesATemporaryLeftByAKilledRunAndNamesAChangedKey) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  RunOptions first = short_run(scene, run);
  first.stop_after_steps = 1000;
  ASSERT_EQ(run_scene(first), 0);
  write(run / "checkpoint.h5.tmp", "left by SIGKILL");
  RunOptions changed = short_run(scene, run);
  changed.resume = true;
  changed.overrides.push_back("inflow.sigma=0.2");
  const std::string why = refusal(changed);
  EXPECT_NE(why.find("scene key inflow.sigma differs"), std::string::npos) << why;
  RunOptions same = short_run(scene, run);
  same.resume = true;
  ASSERT_EQ(run_scene(same), 0);
  EXPECT_FALSE(fs::exists(run / "checkpoint.h5.tmp"));
}

TEST(RunDirectoryOverwrite, RefusesBeforeRemovingAnythingWhenAnOutputIsNotAFile) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  ASSERT_EQ(run_scene(short_run(scene, run)), 0);
  ASSERT_TRUE(fs::exists(run / "run.h5") && fs::exists(run / "summary.json"));
  // A user's folder under an output's name, a FIFO, and a file where figures/ goes.
  const std::vector<std::pair<std::string, std::function<void()>>> plants = {
      {"fields.h5' is a directory",
       [&] {
         fs::remove(run / "fields.h5");
         write(run / "fields.h5" / "mine" / "data.csv", "the user's data");
       }},
      {"run.xmf.tmp' is not a regular file",
       [&] { ASSERT_EQ(::mkfifo((run / "run.xmf.tmp").c_str(), 0644), 0); }},
      {"figures' is not a directory", [&] { write(run / "figures", "a user's file"); }}};
  for (const auto& [expected, plant] : plants) {
    plant();
    const auto before = tree(run);
    RunOptions o = short_run(scene, run);
    o.overwrite = true;
    const std::string why = refusal(o);
    EXPECT_NE(why.find(expected), std::string::npos) << why;
    EXPECT_EQ(tree(run), before) << "a refused --overwrite changed the directory (" << expected
                                 << ")";
    fs::remove_all(run / "fields.h5");
    fs::remove_all(run / "run.xmf.tmp");
    fs::remove_all(run / "figures");
  }
  RunOptions o = short_run(scene, run);
  o.overwrite = true;
  EXPECT_EQ(run_scene(o), 0);
}

TEST(RunDirectoryRefuses, EveryOutputNamePlantedAsASymbolicLink) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const auto outside = tmp.write("outside.txt", "not to be written");
  const fs::path user_dir = tmp.path() / "user";
  write(user_dir / "mach.png", "the user's figure");
  const fs::path run = tmp.path() / "run";
  RunOptions first = short_run(scene, run);
  first.stop_after_steps = 1000;  // resumable
  ASSERT_EQ(run_scene(first), 0);
  std::vector<std::string> names = run_outputs();
  names.push_back("figures");
  for (const std::string& name : names) {
    const fs::path planted = run / name;
    const bool was_file = fs::is_regular_file(fs::symlink_status(planted));
    const fs::path saved = tmp.path() / "saved";
    if (was_file) fs::rename(planted, saved);
    if (name == "figures") fs::remove_all(planted);
    fs::create_directories(planted.parent_path());
    fs::create_symlink(name == "figures" ? user_dir : fs::path(outside), planted);
    for (const bool resume : {false, true}) {
      RunOptions o = short_run(scene, run);
      o.overwrite = !resume;
      o.resume = resume;
      const std::string why = refusal(o);
      EXPECT_NE(why.find("'" + planted.string() + "' is a symbolic link"), std::string::npos)
          << name << (resume ? " --resume: " : " --overwrite: ") << why;
    }
    EXPECT_EQ(read(outside), "not to be written") << name;
    EXPECT_EQ(tree(user_dir),
              (std::map<std::string, std::string>{{"mach.png", "the user's figure"}}))
        << name;
    fs::remove(planted);
    if (was_file) fs::rename(saved, planted);
  }
  RunOptions again = short_run(scene, run);
  again.resume = true;
  EXPECT_EQ(run_scene(again), 0) << "the directory is usable once the links are gone";
}

// An empty marker is a claim cut short (a full disk, kill -9 between creating and
// writing it): the directory is granshock's, in the current format, not "format 0".
TEST(RunDirectoryEmptyMarker, IsTakenAsAClaimThatWasCutShort) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  ASSERT_EQ(run_scene(short_run(scene, run)), 0);
  std::ofstream(run / kRunMarker, std::ios::trunc).close();
  ASSERT_EQ(fs::file_size(run / kRunMarker), 0u);
  RunOptions overwrite = short_run(scene, run);
  overwrite.overwrite = true;
  EXPECT_EQ(refusal(overwrite), "(accepted)");
  EXPECT_NE(read(run / kRunMarker).find("format = 1"), std::string::npos);
  // Without --overwrite it is a marked directory like any other.
  std::ofstream(run / kRunMarker, std::ios::trunc).close();
  EXPECT_NE(refusal(short_run(scene, run)).find("already holds a granshock run"),
            std::string::npos);
  // Nothing but an empty marker: the claim of a new directory that wrote nothing else,
  // taken again by the same command.
  const fs::path fresh = tmp.path() / "fresh";
  fs::create_directories(fresh);
  std::ofstream(fresh / kRunMarker).close();
  EXPECT_EQ(refusal(short_run(scene, fresh)), "(accepted)");
  EXPECT_TRUE(fs::exists(fresh / "run.h5"));
  EXPECT_NE(read(fresh / kRunMarker).find("format = 1"), std::string::npos);
}

// A refused --resume rewrote the marker and removed an empty figures/ (it claimed the
// directory before it read the checkpoint): a refusal leaves the directory as it was.
TEST(RunDirectoryResume, ARefusalLeavesTheDirectoryAsItWas) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  ASSERT_EQ(run_scene(short_run(scene, run)), 0);
  fs::create_directories(run / "figures");
  write(run / kRunMarker, read(run / kRunMarker) + "# another claimant's marker\n");
  const auto before = tree(run);
  const auto marker_time = fs::last_write_time(run / kRunMarker);
  for (const char* duration : {"time.duration=0.0003", "time.duration=0.0001"}) {
    RunOptions shorter = short_run(scene, run);
    shorter.resume = true;
    shorter.overrides.push_back(duration);
    const std::string why = refusal(shorter);
    EXPECT_NE(why.find("time.duration"), std::string::npos) << why;
    EXPECT_EQ(tree(run), before) << duration;
    EXPECT_EQ(fs::last_write_time(run / kRunMarker), marker_time) << duration;
  }
}

// Every file a run writes that has a second name (a hard link) is refused like a
// symbolic link: appending to log.txt or writing run.h5 or the marker in place changed the
// user's file under its other name.
TEST(RunDirectoryRefuses, EveryOutputThatIsAHardLink) {
  TempDir tmp;
  const auto scene = tmp.write("small.toml", small_scene(true));
  const fs::path run = tmp.path() / "run";
  RunOptions first = short_run(scene, run);
  first.stop_after_steps = 1000;
  ASSERT_EQ(run_scene(first), 0);
  for (const char* name : {"log.txt", "run.h5", "checkpoint.h5", kRunMarker}) {
    const fs::path mine = tmp.path() / "mine";
    fs::copy_file(run / name, mine, fs::copy_options::overwrite_existing);
    fs::remove(run / name);
    fs::create_hard_link(mine, run / name);
    const std::string kept = read(mine);
    for (bool resume : {true, false}) {
      RunOptions o = short_run(scene, run);
      o.resume = resume;
      o.overwrite = !resume;
      const std::string why = refusal(o);
      EXPECT_NE(why.find("has 2 hard links"), std::string::npos) << name << ": " << why;
      EXPECT_NE(why.find(name), std::string::npos) << why;
      EXPECT_EQ(read(mine), kept) << name;
    }
    fs::remove(run / name);  // this name only: the user's file stays
    fs::copy_file(mine, run / name);
    fs::remove(mine);
  }
  // The user's own file as the marker: named as a hard link, not as a marker of "format 0".
  const fs::path notes = tmp.path() / "notes.txt";
  write(notes, "my notes\n");
  fs::rename(run / kRunMarker, tmp.path() / "marker");
  fs::create_hard_link(notes, run / kRunMarker);
  RunOptions resume = short_run(scene, run);
  resume.resume = true;
  const std::string why = refusal(resume);
  EXPECT_NE(why.find(".granshock-run' has 2 hard links"), std::string::npos) << why;
  EXPECT_EQ(read(notes), "my notes\n");
  fs::remove(run / kRunMarker);
  fs::rename(tmp.path() / "marker", run / kRunMarker);
  RunOptions again = short_run(scene, run);
  again.resume = true;
  EXPECT_EQ(refusal(again), "(accepted)") << "the directory is usable once the links are gone";
}

// Of two runs claiming one new directory at once, the loser was told the directory "has no
// .granshock-run marker" when it looked between the winner's marker and its check.
TEST(RunDirectoryRace, TheLoserOfANewDirectoryIsToldItIsInUse) {
  TempDir tmp;
  int refusals = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const fs::path dir = tmp.path() / ("new" + std::to_string(trial));
    std::atomic<int> ready{0};
    std::string why[2];
    std::optional<RunDirectory> won[2];
    auto claim = [&](int k) {
      ++ready;
      while (ready < 2) {
      }
      try {
        won[k].emplace(RunDirectory::claim(dir, DirectoryMode::create));
      } catch (const UserError& e) {
        why[k] = e.what();
      }
    };
    std::thread a(claim, 0), b(claim, 1);
    a.join();
    b.join();
    EXPECT_EQ(int(won[0].has_value()) + int(won[1].has_value()), 1) << trial;
    for (const std::string& w : why) {
      if (w.empty()) continue;
      ++refusals;
      EXPECT_NE(w.find("in use by another granshock"), std::string::npos) << trial << ": " << w;
    }
  }
  EXPECT_EQ(refusals, 200);
}

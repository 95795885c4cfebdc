// Input files are read only when regular (io/regular_file.hpp): a FIFO as the scene or as
// checkpoint.h5 on --resume blocked granshock forever. Each refusal must come at once,
// as one UserError naming what the file is.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "analysis/summary_json.hpp"
#include "cases/study/case_directory.hpp"
#include "cases/study/study_file.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/io_test_support.hpp"
#include "io/regular_file.hpp"
#include "io/run_file.hpp"
#include "io/scene_file.hpp"

namespace granshock {
namespace {

using test::TempDir;

template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "(accepted)";
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(RegularFile, AFifoIsRefusedWithoutBlocking) {
  TempDir dir;
  const auto fifo = dir / "s.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refusal([&] { load_scene_file(fifo, {}); }),
            "scene file '" + fifo.string() + "' is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(refusal([&] {
              CheckpointExtras extras;
              read_checkpoint(fifo, extras);
            }),
            "checkpoint '" + fifo.string() + "' is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(refusal([&] { RunFile::open_for_append(fifo); }),
            "run file '" + fifo.string() + "' is a FIFO (named pipe), not a regular file");
  EXPECT_EQ(refusal([&] { load_study_file(fifo); }),
            "study file '" + fifo.string() + "' is a FIFO (named pipe), not a regular file");
}

// summary.json, read by `fields` (merged into) and by `study --collect`.
TEST(RegularFile, AFifoSummaryIsRefusedWithoutBlocking) {
  TempDir dir;
  const auto fifo = dir / "summary.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string expected =
      "summary '" + fifo.string() + "' is a FIFO (named pipe), not a regular file";
  EXPECT_EQ(refusal([&] { merge_summary_json(fifo, {{"a", 1}}); }), expected);
  EXPECT_EQ(refusal([&] { read_summary(dir.path()); }), expected);
}

TEST(RegularFile, DevicesAndDirectoriesAreRefused) {
  TempDir dir;
  EXPECT_EQ(refusal([] { require_regular_file("/dev/zero", "scene file"); }),
            "scene file '/dev/zero' is a character device, not a regular file");
  EXPECT_EQ(refusal([&] { require_regular_file(dir.path(), "trade table"); }),
            "trade table '" + dir.path().string() + "' is a directory, not a regular file");
  EXPECT_EQ(refusal([&] { require_regular_file(dir / "none", "study file"); }),
            "cannot read study file '" + (dir / "none").string() + "': no such file");
}

TEST(RegularFile, LinksAreFollowedOrRefusedAsAsked) {
  TempDir dir;
  write(dir / "target", "x = 1\n");
  std::filesystem::create_symlink(dir / "target", dir / "link");
  EXPECT_EQ(read_regular_file(dir / "link", "scene file", 100), "x = 1\n");
  EXPECT_EQ(refusal([&] { read_regular_file(dir / "link", "summary", 100, Links::refuse); }),
            "summary '" + (dir / "link").string() + "' is a symbolic link, not a regular file");
}

TEST(RegularFile, ReadsWholeFilesUpToTheBound) {
  TempDir dir;
  const std::string text(70000, 'a');  // more than one read's buffer
  write(dir / "f", text);
  EXPECT_EQ(read_regular_file(dir / "f", "scene file", text.size()), text);
  EXPECT_EQ(refusal([&] { read_regular_file(dir / "f", "scene file", text.size() - 1); }),
            "scene file '" + (dir / "f").string() + "' is longer than 69999 bytes");
  write(dir / "empty", "");
  EXPECT_EQ(read_regular_file(dir / "empty", "scene file", 10), "");
}

// A huge regular file (sparse: no disk used) is refused after the bound, not read whole.
TEST(RegularFile, AHugeSceneIsRefusedAtTheBound) {
  TempDir dir;
  { std::ofstream(dir / "huge.toml"); }
  std::filesystem::resize_file(dir / "huge.toml", std::uintmax_t(1) << 34);
  EXPECT_EQ(refusal([&] { load_scene_file(dir / "huge.toml", {}); }),
            "scene file '" + (dir / "huge.toml").string() + "' is longer than " +
                std::to_string(kMaxSceneFileBytes) + " bytes");
}

}  // namespace
}  // namespace granshock

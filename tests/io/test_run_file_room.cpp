// run.h5 on a full disk (docs/output_format.md, "A full disk"): a file-size limit met at any
// point refuses the change before HDF5 writes anything, and the file, closed under the same
// limit, reopens with every entry written before; and the run id and entry counts that tie
// run.h5 to a checkpoint ("What a resume checks").
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "core/user_error.hpp"
#include "io/io_test_support.hpp"
#include "io/run_file.hpp"
#include "io/run_file_growth.hpp"

namespace granshock {
namespace {

using test::random_particles;
using test::TempDir;

TimeSeriesRow row_at(long step) {
  TimeSeriesRow row;
  row.step = step;
  row.time = 1e-6 * double(step);
  row.particles = step;
  row.kinetic_energy = 0.5 * double(step);
  return row;
}

// The soft file-size limit of this process, as `ulimit -f` sets it for granshock; writes
// past it fail with EFBIG (SIGXFSZ ignored, as apps/granshock/main.cpp does).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_)(int) = SIG_DFL;
};

// What a run does to run.h5, change by change: rows with every step (past one chunk of
// rows), frames of incompressible particles now and then, whose number grows past one
// chunk of particles once earlier frames are many (all of them gain the new chunks), an
// empty frame, and the field sums and attributes at the end.
struct Change {
  int frames = 0, rows = 0;  // the entries it appends
  std::function<void(RunFile&)> apply;
};

std::vector<Change> changes() {
  std::vector<Change> all;
  const std::vector<int> large = {17000, 0, 2000};
  long step = 0;
  for (int k = 0; k < 264; ++k) {
    step += 10;
    all.push_back({0, 1, [step](RunFile& f) { f.append_time_series(row_at(step)); }});
    if (k % 10 == 0 || k >= 261) {
      const int n = k < 261 ? 50 + k : large[std::size_t(k - 261)];
      all.push_back({1, 0, [step, n](RunFile& f) {
                       f.append_snapshot(step, 1e-6 * double(step), random_particles(n));
                     }});
    }
  }
  all.push_back({0, 0, [](RunFile& f) {
                   f.write_array("/fields/grid/sums", std::vector<double>(100000, 1.5), {100000});
                   f.write_attribute("/fields/grid", "nx", 40L);
                   f.flush();
                 }});
  return all;
}

struct Written {
  long frames = 0, rows = 0;
};

// Applies the changes under the limit until one is refused: the entries appended.
Written apply_until_refused(const std::filesystem::path& path, int dim, rlim_t limit,
                            std::string& refusal) {
  Written done;
  std::optional<RunFile> file(RunFile::create(path, "", "", dim));
  {
    const FileSizeLimit full(limit);
    try {
      for (const Change& change : changes()) {
        change.apply(*file);
        done.frames += change.frames;
        done.rows += change.rows;
      }
    } catch (const UserError& e) {
      refusal = e.what();
    }
    file.reset();  // closed on the full disk, as when the run ends there
  }
  return done;
}

class RunFileOnAFullDisk : public ::testing::TestWithParam<int> {};

TEST_P(RunFileOnAFullDisk, IsRefusedBeforeAnyWriteAndKeepsEveryEntryBefore) {
  const int dim = GetParam();
  TempDir dir;
  std::uintmax_t full_size = 0;
  {
    std::string none;
    apply_until_refused(dir / "unlimited.h5", dim, RLIM_INFINITY, none);
    ASSERT_EQ(none, "");
    full_size = std::filesystem::file_size(dir / "unlimited.h5");
  }
  const int limits = 14;
  int refused = 0;
  for (int k = 1; k < limits; ++k) {
    const rlim_t limit = rlim_t(full_size * std::uintmax_t(k) / limits);
    const auto path = dir / ("limited" + std::to_string(k) + ".h5");
    std::string refusal;
    const Written done = apply_until_refused(path, dim, limit, refusal);
    if (refusal.empty()) continue;  // the file was created within the limit... all of it
    ++refused;
    // A refusal, never a failed HDF5 write (which can leave the file unreadable).
    EXPECT_NE(refusal.find("no room for"), std::string::npos)
        << "limit " << limit << ": " << refusal;
    EXPECT_NE(refusal.find("File too large"), std::string::npos) << refusal;
    try {
      const RunFile back = RunFile::open_read_only(path);
      EXPECT_EQ(long(back.frames().size()), done.frames) << "limit " << limit;
      EXPECT_EQ(back.record().rows, done.rows) << "limit " << limit;
    } catch (const UserError& e) {
      ADD_FAILURE() << "limit " << limit << " bytes: the file does not reopen after the refusal ("
                    << refusal << "): " << e.what();
    }
  }
  EXPECT_GT(refused, limits / 2);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, RunFileOnAFullDisk, ::testing::Values(2, 3));

TEST(RunFileRoom, AFlushGivesBackTheRoomNotUsed) {
  TempDir dir;
  RunFile file = RunFile::create(dir / "run.h5", "", "", 2);
  file.append_snapshot(10, 1e-5, random_particles(3000));
  const std::uintmax_t after_frame = std::filesystem::file_size(dir / "run.h5");
  // The frame's bound (a whole chunk of particles, deflate's worst case) is far above its
  // size; none of it stays in the file.
  // (position and velocity: 2 float64 per particle, species and id: one int32.)
  const std::vector<run_growth::ParticleArray> arrays = {
      {16384, 16}, {16384, 16}, {16384, 4}, {16384, 4}};
  EXPECT_LT(after_frame, run_growth::snapshot_rows(0, 0, 3000, arrays) / 2);
  file.write_attribute("/summary", "note", std::string(1000, 'x'));
  file.flush();
  EXPECT_LT(std::filesystem::file_size(dir / "run.h5"), after_frame + 16384);
}

// --- the run id and the record a checkpoint keeps of run.h5 ---------------------------

void write_run(const std::filesystem::path& path, int frames, RunFileRecord* at_frame_2) {
  RunFile file = RunFile::create(path, "", "", 2);
  for (int f = 1; f <= frames; ++f) {
    file.append_time_series(row_at(100 * f));
    file.append_snapshot(100 * f, 1e-4 * f, random_particles(10 * f));
    if (f == 2 && at_frame_2 != nullptr) *at_frame_2 = file.record();
  }
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string refusal_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(RunFileRecord, EveryRunHasItsOwnIdAndTheRecordCountsEntries) {
  TempDir dir;
  RunFileRecord a, b;
  write_run(dir / "a.h5", 3, &a);
  write_run(dir / "b.h5", 3, &b);
  EXPECT_EQ(a.run_id.size(), 32u) << a.run_id;
  EXPECT_NE(a.run_id, b.run_id);
  EXPECT_EQ(a.frames, 2);
  EXPECT_EQ(a.rows, 2);
  EXPECT_EQ(RunFile::open_read_only(dir / "a.h5").record().frames, 3);
}

TEST(RunFileRecord, ResumeRefusesAFileTheCheckpointWasNotWrittenWithAndChangesNothing) {
  TempDir dir;
  RunFileRecord at_2, other_run;
  write_run(dir / "run.h5", 4, &at_2);
  write_run(dir / "other.h5", 4, &other_run);
  const std::string before = bytes_of(dir / "run.h5");

  // Another run's checkpoint (the same step and counts).
  std::string refusal =
      refusal_of([&] { RunFile::open_for_resume(dir / "run.h5", 200, other_run); });
  EXPECT_NE(refusal.find("belongs to another run"), std::string::npos) << refusal;
  // A later checkpoint of this run than run.h5 holds: it recorded more entries.
  RunFileRecord later = at_2;
  later.frames = 5;
  later.rows = 5;
  refusal = refusal_of([&] { RunFile::open_for_resume(dir / "run.h5", 500, later); });
  EXPECT_NE(refusal.find("holds 4 snapshots and 4 time-series rows up to step 500"),
            std::string::npos)
      << refusal;
  EXPECT_NE(refusal.find("written when it held 5 and 5"), std::string::npos) << refusal;
  // An older run.h5 than the checkpoint: one frame short.
  RunFileRecord one_more = at_2;
  one_more.frames = 3;
  refusal = refusal_of([&] { RunFile::open_for_resume(dir / "run.h5", 200, one_more); });
  EXPECT_NE(refusal.find("holds 2 snapshots"), std::string::npos) << refusal;
  EXPECT_EQ(refusal.find('\n'), std::string::npos);
  EXPECT_EQ(bytes_of(dir / "run.h5"), before) << "a refused resume changed run.h5";

  // The checkpoint's own file: accepted, cut back to its step.
  RunFile resumed = RunFile::open_for_resume(dir / "run.h5", 200, at_2);
  EXPECT_EQ(resumed.frames().size(), 2u);
}

// The file without its @run_id, its root saying format `format`.
void remove_run_id(const std::filesystem::path& path, int format) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  ASSERT_GE(H5Adelete(f, "run_id"), 0);
  const hid_t a = H5Aopen(f, "granshock_format_version", H5P_DEFAULT);
  ASSERT_GE(H5Awrite(a, H5T_NATIVE_INT, &format), 0);
  H5Aclose(a);
  H5Fclose(f);
}

// A checkpoint without a record (format 3 written before run ids) is not checked (run.h5
// may already have an id: a resume from it that stopped before its first checkpoint), and
// a format-2 file without an id gets one; a checkpoint with a record refuses a file without
// an id.
TEST(RunFileRecord, FilesAndCheckpointsFromBeforeRunIds) {
  TempDir dir;
  write_run(dir / "run.h5", 2, nullptr);
  remove_run_id(dir / "run.h5", 2);  // as format 2 left it: format 3 always holds one
  RunFileRecord recorded;
  recorded.run_id = "0123456789abcdef0123456789abcdef";
  recorded.frames = recorded.rows = 1;
  const std::string refusal =
      refusal_of([&] { RunFile::open_for_resume(dir / "run.h5", 100, recorded); });
  EXPECT_NE(refusal.find("(run id none: it is older than run ids, the checkpoint's "
                         "'0123456789abcdef0123456789abcdef')"),
            std::string::npos)
      << refusal;
  std::string id;
  {
    RunFile resumed = RunFile::open_for_resume(dir / "run.h5", 100, RunFileRecord{});
    EXPECT_EQ(resumed.frames().size(), 1u);
    id = resumed.record().run_id;
    EXPECT_EQ(id.size(), 32u);
  }
  // Again from the same old checkpoint: the file's new id is no obstacle, nor changed.
  RunFile again = RunFile::open_for_resume(dir / "run.h5", 100, RunFileRecord{});
  EXPECT_EQ(again.record().run_id, id);
}

// Format 3 gives every run file a run id when it is made: one without was edited or
// damaged, and a resume refuses it with the file unchanged, whatever the checkpoint holds.
TEST(RunFileRecord, FormatThreeWithoutARunIdIsRefused) {
  TempDir dir;
  write_run(dir / "run.h5", 2, nullptr);
  remove_run_id(dir / "run.h5", kRunFileFormat);
  const std::string before = bytes_of(dir / "run.h5");
  const std::string refusal =
      refusal_of([&] { RunFile::open_for_resume(dir / "run.h5", 100, RunFileRecord{}); });
  EXPECT_NE(refusal.find("has no @run_id, which every run file of format 3 holds"),
            std::string::npos)
      << refusal;
  EXPECT_EQ(bytes_of(dir / "run.h5"), before) << "a refused resume changed run.h5";
}

}  // namespace
}  // namespace granshock

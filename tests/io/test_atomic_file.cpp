// The atomic writers (io/atomic_file.hpp, h5::write_file_atomically) write only files
// they create themselves: a symbolic link planted under the temporary's name is refused
// and what it points to stays unchanged, a stale temporary that is a regular file is
// replaced, a link at the target is replaced by the file instead of being written
// through, and a write that fails on a full disk (a file-size limit) leaves no temporary.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <fstream>
#include <functional>
#include <sstream>

#include "core/user_error.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_helpers.hpp"
#include "io_test_support.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "(accepted)";
}

// The two writers with the same signature: text, and an HDF5 file with one attribute.
using Writer = std::function<void(const fs::path&)>;
const Writer kText = [](const fs::path& p) { write_file_atomically(p, "granshock's text\n"); };
const Writer kHdf5 = [](const fs::path& p) {
  h5::write_file_atomically(p, "test file", [](hid_t file) {
    h5::write_attribute(file, "granshock_file", "test");
    h5::write_dataset(file, "/values", std::vector<double>(4000, 1.5), {4000});
  });
};

// A file-size limit of `kib` KiB for the scope (writes past it fail with EFBIG, as on a
// full disk), with SIGXFSZ ignored as granshock's main() does.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t kib) {
    getrlimit(RLIMIT_FSIZE, &old_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = old_;
    limit.rlim_cur = kib * 1024;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit old_{};
  void (*old_handler_)(int) = nullptr;
};

}  // namespace

TEST(AtomicFile, NeverWritesThroughALinkPlantedAsItsTemporary) {
  for (const auto& [name, writer] : {std::pair{"text", kText}, std::pair{"hdf5", kHdf5}}) {
    test::TempDir tmp;
    write(tmp / "outside", "the user's file");
    const fs::path target = tmp / "out";
    fs::create_symlink(tmp / "outside", target.string() + ".tmp");
    const std::string why = refusal([&, w = writer] { w(target); });
    EXPECT_NE(why.find("out.tmp' is a symbolic link"), std::string::npos) << name << ": " << why;
    EXPECT_EQ(read(tmp / "outside"), "the user's file") << name;
    EXPECT_TRUE(fs::is_symlink(target.string() + ".tmp")) << name << ": a user's link removed";
    EXPECT_FALSE(fs::exists(fs::symlink_status(target))) << name;
    // A dangling link is refused too (O_CREAT would create its target).
    fs::remove(target.string() + ".tmp");
    fs::create_symlink(tmp / "not-yet", target.string() + ".tmp");
    EXPECT_NE(refusal([&, w = writer] { w(target); }).find("symbolic link"), std::string::npos);
    EXPECT_FALSE(fs::exists(tmp / "not-yet")) << name;
  }
}

TEST(AtomicFile, ReplacesAStaleTemporaryAndALinkAtTheTarget) {
  for (const auto& [name, writer] : {std::pair{"text", kText}, std::pair{"hdf5", kHdf5}}) {
    test::TempDir tmp;
    write(tmp / "outside", "the user's file");
    const fs::path target = tmp / "out";
    write(target.string() + ".tmp", "left by a killed run");
    fs::create_symlink(tmp / "outside", target);
    writer(target);
    EXPECT_FALSE(fs::exists(fs::symlink_status(target.string() + ".tmp"))) << name;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(target))) << name;
    EXPECT_EQ(read(tmp / "outside"), "the user's file") << name;
  }
}

TEST(AtomicFile, ADirectoryAsItsTemporaryIsRefused) {
  test::TempDir tmp;
  fs::create_directories(tmp / "out.tmp" / "sub");
  EXPECT_NE(refusal([&] { kText(tmp / "out"); }).find("out.tmp' is a directory"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(tmp / "out.tmp" / "sub"));
}

TEST(AtomicFile, AFullDiskLeavesNoTemporaryAndThePreviousFile) {
  // 0 KiB: the HDF5 file cannot even be created; 1 and 8 KiB: its data does not fit.
  for (const rlim_t kib : {0, 1, 8}) {
    for (const auto& [name, writer] : {std::pair{"text", kText}, std::pair{"hdf5", kHdf5}}) {
      if (std::string(name) == "text" && kib > 0) continue;  // the text fits
      test::TempDir tmp;
      const fs::path target = tmp / "out";
      write(target, "the previous version");
      std::string why;
      {
        const FileSizeLimit full(kib);
        why = refusal([&, w = writer] { w(target); });
      }
      EXPECT_NE(why.find("File too large"), std::string::npos) << name << " " << kib << ": " << why;
      EXPECT_FALSE(fs::exists(fs::symlink_status(target.string() + ".tmp")))
          << name << " at " << kib << " KiB left its temporary";
      EXPECT_EQ(read(target), "the previous version") << name;
    }
  }
}

TEST(MakeRealDirectory, CreatesOneAndRefusesALinkOrAFile) {
  test::TempDir tmp;
  make_real_directory(tmp / "figures");
  EXPECT_TRUE(fs::is_directory(fs::symlink_status(tmp / "figures")));
  make_real_directory(tmp / "figures");  // again: it is there
  fs::create_directories(tmp / "user");
  fs::create_symlink(tmp / "user", tmp / "linked");
  EXPECT_NE(refusal([&] { make_real_directory(tmp / "linked"); }).find("is a symbolic link"),
            std::string::npos);
  write(tmp / "file", "x");
  EXPECT_NE(refusal([&] { make_real_directory(tmp / "file"); }).find("is a regular file where"),
            std::string::npos);
}

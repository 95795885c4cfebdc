#include "run_directory.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include "user_error.hpp"
#include "version.hpp"

namespace granshock {

namespace fs = std::filesystem;

const std::vector<std::string>& run_outputs() {
  // run.h5 and its XDMF (io/run_file.cpp, io/xdmf_writer.cpp), the checkpoint and the
  // summary (cases/bow_shock/run_command.cpp), the fields (analysis/fields_output.cpp)
  // and the figures drawn by analysis/plot_fields.py. Atomic writers use NAME.tmp.
  static const std::vector<std::string> outputs = [] {
    const std::vector<std::string> atomic = {"run.xmf",      "checkpoint.h5",
                                             "summary.json", "fields.h5",
                                             "fields.xmf",   "detachment_convergence.csv"};
    std::vector<std::string> all = {"run.h5", "figures/solid_fraction.png",
                                    "figures/temperature.png", "figures/mach.png",
                                    "figures/stagnation_profiles.png"};
    for (const auto& name : atomic) {
      all.push_back(name);
      all.push_back(name + ".tmp");
    }
    return all;
  }();
  return outputs;
}

namespace {

struct Marker {
  int format = 0;
  long pid = 0;
  std::string version;
};

// The marker of `dir`, if it has one. A marker that is not a regular file is refused,
// so that granshock never follows a link planted in its place.
std::optional<Marker> read_marker(const fs::path& dir) {
  const fs::path path = dir / kRunMarker;
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (ec || !fs::exists(status)) return std::nullopt;
  if (!fs::is_regular_file(status))
    throw UserError(
        fmt::format("'{}' is not a regular file; it cannot mark a granshock run "
                    "directory: remove it or choose another directory",
                    path.string()));
  std::ifstream in(path);
  Marker m;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string key, eq, value;
    if (!(fields >> key >> eq >> value) || eq != "=") continue;
    if (key == "format") m.format = std::atoi(value.c_str());
    if (key == "pid") m.pid = std::atol(value.c_str());
    if (key == "version") m.version = value;
  }
  return m;
}

bool is_empty_directory(const fs::path& dir) {
  std::error_code ec;
  return fs::is_empty(dir, ec) && !ec;
}

// Whether another process holds the run lock of `dir` (a marker must exist).
bool locked_by_another_run(const fs::path& dir) {
  const int fd = ::open((dir / kRunMarker).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool locked = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);  // also releases the lock if we got it
  return locked;
}

void refuse_locked(const fs::path& dir, const Marker& marker) {
  throw UserError(fmt::format(
      "output directory '{}' is in use by another granshock run{}; wait for it to end or "
      "stop it, then try again",
      dir.string(), marker.pid > 0 ? fmt::format(" (pid {})", marker.pid) : ""));
}

// The nearest existing ancestor must be a writable directory for create_directories.
void check_creatable(const fs::path& dir) {
  fs::path probe = fs::absolute(dir);
  std::error_code ec;
  while (!probe.empty() && !fs::exists(probe, ec) && probe != probe.parent_path())
    probe = probe.parent_path();
  if (!fs::is_directory(probe, ec))
    throw UserError(fmt::format("output directory '{}': '{}' is not a directory", dir.string(),
                                probe.string()));
  if (::access(probe.c_str(), W_OK | X_OK) != 0)
    throw UserError(
        fmt::format("output directory '{}': '{}' is not writable", dir.string(), probe.string()));
}

void check_no_linked_outputs(const fs::path& dir) {
  for (const std::string& name : run_outputs()) {
    for (fs::path p = dir / name; p != dir; p = p.parent_path()) {
      std::error_code ec;
      if (fs::is_symlink(fs::symlink_status(p, ec)))
        throw UserError(fmt::format(
            "'{}' is a symbolic link; granshock writes its outputs only as files it creates "
            "itself: remove the link or choose another directory",
            p.string()));
    }
  }
}

void remove_outputs(const fs::path& dir, bool temporaries_only) {
  for (const std::string& name : run_outputs()) {
    if (temporaries_only && name.size() < 4) continue;
    if (temporaries_only && name.compare(name.size() - 4, 4, ".tmp") != 0) continue;
    std::error_code ec;
    fs::remove(dir / name, ec);  // a file (links were refused by the check)
    if (ec)
      throw UserError(fmt::format("cannot remove '{}': {}", (dir / name).string(), ec.message()));
  }
  std::error_code ec;
  if (!temporaries_only && is_empty_directory(dir / "figures")) fs::remove(dir / "figures", ec);
}

void write_marker(int fd, const fs::path& path) {
  const std::string text = fmt::format(
      "granshock run directory: granshock removes only its own outputs here\n"
      "format = {}\nversion = {}\npid = {}\n",
      kRunDirectoryFormat, GRANSHOCK_VERSION_STRING, long(::getpid()));
  if (::ftruncate(fd, 0) != 0 ||
      ::pwrite(fd, text.data(), text.size(), 0) != ssize_t(text.size()) || ::fsync(fd) != 0)
    throw UserError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
}

}  // namespace

void RunDirectory::check(const fs::path& dir, DirectoryMode mode) {
  if (dir.empty()) throw UserError("the output directory name is empty");
  std::error_code ec;
  const bool exists = fs::exists(dir, ec);
  if (exists && !fs::is_directory(dir, ec))
    throw UserError(
        fmt::format("output directory '{}' exists and is not a directory", dir.string()));
  if (!exists) {
    if (mode == DirectoryMode::resume)
      throw UserError(fmt::format("--resume: output directory '{}' does not exist", dir.string()));
    check_creatable(dir);
    return;
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw UserError(fmt::format("output directory '{}' is not writable", dir.string()));

  const std::optional<Marker> marker = read_marker(dir);
  if (!marker) {
    if (is_empty_directory(dir)) {
      if (mode == DirectoryMode::resume)
        throw UserError(
            fmt::format("--resume: '{}' is empty; there is no run to resume", dir.string()));
      return;  // an empty directory is claimed as it is
    }
    const bool old_run = fs::exists(dir / "run.h5", ec) || fs::exists(dir / "checkpoint.h5", ec);
    throw UserError(fmt::format(
        "output directory '{}' is not empty and is not a granshock run directory (it has no "
        "{} marker){}; granshock never deletes or resumes files it did not create: choose a "
        "new or empty directory with --out",
        dir.string(), kRunMarker,
        old_run ? ", though it holds run files, perhaps from a granshock before 0.2 that did not "
                  "mark its directories: move them away yourself"
                : ""));
  }
  if (marker->format != kRunDirectoryFormat)
    throw UserError(fmt::format(
        "output directory '{}' was written by granshock {} in run-directory format {}; this "
        "granshock {} reads format {}: use that version, or another directory",
        dir.string(), marker->version.empty() ? "(unknown version)" : marker->version,
        marker->format, GRANSHOCK_VERSION_STRING, kRunDirectoryFormat));
  if (locked_by_another_run(dir)) refuse_locked(dir, *marker);
  check_no_linked_outputs(dir);
  if (mode == DirectoryMode::create)
    throw UserError(fmt::format(
        "output directory '{}' already holds a granshock run; use --overwrite to replace its "
        "files or --resume to continue it",
        dir.string()));
  if (mode == DirectoryMode::resume && !fs::exists(dir / "checkpoint.h5", ec) &&
      fs::exists(dir / "run.h5", ec))
    throw UserError(fmt::format(
        "--resume: '{}' holds run.h5 but no checkpoint.h5: the run was stopped before its "
        "first checkpoint; start again with --overwrite",
        dir.string()));
  if (mode == DirectoryMode::resume &&
      (!fs::exists(dir / "checkpoint.h5", ec) || !fs::exists(dir / "run.h5", ec)))
    throw UserError(fmt::format("--resume: '{}' holds no checkpoint.h5 and run.h5 to resume from",
                                dir.string()));
}

RunDirectory RunDirectory::claim(const fs::path& dir, DirectoryMode mode) {
  check(dir, mode);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw UserError(
        fmt::format("cannot create output directory '{}': {}", dir.string(), ec.message()));
  const fs::path marker_path = dir / kRunMarker;
  const bool marked = fs::exists(fs::symlink_status(marker_path, ec));
  // O_EXCL: of two runs claiming the same empty directory at once, one creates the marker.
  const int fd = ::open(marker_path.c_str(),
                        O_RDWR | O_CLOEXEC | O_NOFOLLOW | (marked ? 0 : O_CREAT | O_EXCL), 0644);
  if (fd < 0) {
    if (errno == EEXIST) refuse_locked(dir, Marker{});
    throw UserError(
        fmt::format("cannot write '{}': {}", marker_path.string(), std::strerror(errno)));
  }
  RunDirectory claimed(dir, fd);  // closes fd on any throw below
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) refuse_locked(dir, read_marker(dir).value_or(Marker{}));
  write_marker(fd, marker_path);
  if (mode == DirectoryMode::overwrite) remove_outputs(dir, false);
  if (mode == DirectoryMode::resume) remove_outputs(dir, true);  // left by a killed run
  return claimed;
}

RunDirectory::RunDirectory(RunDirectory&& other) noexcept
    : dir_(std::move(other.dir_)), lock_fd_(other.lock_fd_) {
  other.lock_fd_ = -1;
}

RunDirectory& RunDirectory::operator=(RunDirectory&& other) noexcept {
  if (this != &other) {
    if (lock_fd_ >= 0) ::close(lock_fd_);
    dir_ = std::move(other.dir_);
    lock_fd_ = other.lock_fd_;
    other.lock_fd_ = -1;
  }
  return *this;
}

RunDirectory::~RunDirectory() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // closing the descriptor releases the flock
}

}  // namespace granshock

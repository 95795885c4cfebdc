#include "io/marked_directory.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "core/user_error.hpp"
#include "version.hpp"

namespace granshock {

namespace fs = std::filesystem;

std::optional<DirectoryMarker> read_marker(const fs::path& dir, const char* name) {
  const fs::path path = dir / name;
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return std::nullopt;
  if (!S_ISREG(st.st_mode))
    throw UserError(fmt::format(
        "'{}' is not a regular file; it cannot mark a granshock directory: remove it or choose "
        "another directory",
        path.string()));
  DirectoryMarker m;
  m.empty = st.st_size == 0;
  m.path = path;
  m.links = st.st_nlink;
  std::ifstream in(path);
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

void check_marker_format(const fs::path& dir, const DirectoryMarker& marker, int format,
                         const std::string& kind) {
  // An empty marker is granshock's own claim, interrupted: a claim creates the marker
  // with O_CREAT | O_EXCL and writes its lines at once, so a 0-byte marker is one whose
  // write failed (a full disk) or never came (kill -9), and nothing but granshock creates
  // a file of that name (a user who does means to mark the directory). It is taken as a
  // marker of the current format, and the next claim writes it whole: refusing it would
  // leave a directory that only deleting the marker by hand could free again.
  if (marker.links > 1) refuse_hard_link(marker.path, marker.links);
  if (marker.empty || marker.format == format) return;
  throw UserError(fmt::format(
      "output directory '{}' was written by granshock {} in {} format {}; this granshock {} "
      "reads format {}: use that version, or another directory",
      dir.string(), marker.version.empty() ? "(unknown version)" : marker.version, kind,
      marker.format, GRANSHOCK_VERSION_STRING, format));
}

bool locked_by_another(const fs::path& dir, const char* name) {
  const int fd = ::open((dir / name).c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  const bool locked = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);  // also releases the lock if we got it
  return locked;
}

bool locked_for_writing(const fs::path& dir, const char* name) {
  const int fd = ::open((dir / name).c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  const bool locked = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return locked;
}

void refuse_in_use(const fs::path& dir, const DirectoryMarker& marker) {
  throw UserError(fmt::format(
      "output directory '{}' is in use by another granshock run or fields command{}; wait for "
      "it to end or "
      "stop it, then try again",
      dir.string(), marker.pid > 0 ? fmt::format(" (pid {})", marker.pid) : ""));
}

bool directory_is_empty(const fs::path& dir) {
  std::error_code ec;
  return fs::is_empty(dir, ec) && !ec;
}

bool holds_only_an_empty_marker(const fs::path& dir, const char* name) {
  std::error_code ec;
  auto it = fs::directory_iterator(dir, ec);
  if (ec || it == fs::directory_iterator() || it->path().filename() != name) return false;
  struct stat st {};
  const bool empty_marker =
      ::lstat(it->path().c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size == 0;
  return empty_marker && ++it == fs::directory_iterator();
}

void check_creatable(const fs::path& dir) {
  fs::path probe = fs::absolute(dir), first_missing;
  std::error_code ec;
  while (!probe.empty() && !fs::exists(probe, ec) && probe != probe.parent_path()) {
    first_missing = probe;
    probe = probe.parent_path();
  }
  if (!fs::is_directory(probe, ec))
    throw UserError(fmt::format("output directory '{}': '{}' is not a directory", dir.string(),
                                probe.string()));
  if (::access(probe.c_str(), W_OK | X_OK) != 0)
    throw UserError(
        fmt::format("output directory '{}': '{}' is not writable", dir.string(), probe.string()));
  // access() says yes to root wherever the mode bits would, in /proc as on a file system
  // that takes no new directory: a directory of this process' own name is made there and
  // removed again, so that --dry-run knows what the run will meet. Not the target itself:
  // another command may be creating it at this moment.
  if (!first_missing.empty()) {
    const fs::path trial = probe / fmt::format(".granshock-mkdir-probe.{}", long(::getpid()));
    if (::mkdir(trial.c_str(), 0700) != 0 && errno != EEXIST)
      throw UserError(fmt::format("output directory '{}' cannot be created in '{}': {}",
                                  dir.string(), probe.string(), std::strerror(errno)));
    ::rmdir(trial.c_str());
  }
}

namespace {

[[noreturn]] void refuse_output(const fs::path& p, const std::string& is,
                                const std::string& remedy) {
  throw UserError(fmt::format(
      "'{}' is {}; granshock writes its outputs only as files it creates itself: {} or choose "
      "another directory",
      p.string(), is, remedy));
}

}  // namespace

void refuse_hard_link(const fs::path& path, unsigned long links) {
  throw UserError(fmt::format(
      "'{}' has {} hard links: it is also another file, which granshock would change by "
      "writing this one; granshock writes its outputs only as files it creates itself: remove "
      "this name (the other names keep the file) or choose another directory",
      path.string(), links));
}

void check_outputs_are_files(const fs::path& dir, const std::vector<std::string>& outputs) {
  for (const std::string& name : outputs) {
    fs::path p = dir;
    const fs::path relative(name);
    for (auto part = relative.begin(); part != relative.end(); ++part) {
      p /= *part;
      const bool leaf = std::next(part) == relative.end();
      struct stat st {};
      if (::lstat(p.c_str(), &st) != 0) break;  // absent: so is everything below it
      if (S_ISLNK(st.st_mode)) refuse_output(p, "a symbolic link", "remove the link");
      if (leaf && S_ISDIR(st.st_mode))
        refuse_output(p, "a directory where granshock writes a file", "move it away");
      if (leaf && !S_ISREG(st.st_mode))
        refuse_output(p, "not a regular file (granshock writes a file there)", "remove it");
      if (leaf && st.st_nlink > 1) refuse_hard_link(p, st.st_nlink);
      if (!leaf && !S_ISDIR(st.st_mode))
        refuse_output(p, "not a directory (granshock writes files into it)", "move it away");
    }
  }
}

void remove_outputs(const fs::path& dir, const std::vector<std::string>& outputs) {
  std::set<fs::path> subdirectories;
  for (const std::string& name : outputs) {
    const fs::path path = dir / name;
    if (::unlink(path.c_str()) != 0) {
      if (errno == ENOENT) continue;
      throw UserError(fmt::format("cannot remove '{}': {}", path.string(), std::strerror(errno)));
    }
    if (fs::path(name).has_parent_path()) subdirectories.insert(dir / fs::path(name).parent_path());
  }
  // Only those granshock emptied, and only when empty: a directory that held none of these
  // outputs stays as it was.
  for (const fs::path& sub : subdirectories) ::rmdir(sub.c_str());
}

namespace {

// A marker with more than one name is someone else's file too: writing it (the pid line)
// would change that file (refuse_hard_link).
void refuse_hard_linked_marker(const fs::path& path, int fd) {
  struct stat st {};
  if (::fstat(fd, &st) == 0 && st.st_nlink > 1) refuse_hard_link(path, st.st_nlink);
}

}  // namespace

DirectoryLock DirectoryLock::take(const fs::path& dir, const char* name, const std::string& header,
                                  int format) {
  const fs::path path = dir / name;
  struct stat st {};
  const bool marked = ::lstat(path.c_str(), &st) == 0;
  const int fd =
      ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW | (marked ? 0 : O_CREAT | O_EXCL), 0644);
  if (fd < 0) {
    if (errno == EEXIST) refuse_in_use(dir, DirectoryMarker{});
    throw UserError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
  }
  DirectoryLock lock(fd);  // closes fd on any throw below
  lock.dir_ = dir;
  lock.name_ = name;
  lock.created_ = !marked;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
    refuse_in_use(dir, read_marker(dir, name).value_or(DirectoryMarker{}));
  lock.stamp(header, format);
  return lock;
}

DirectoryLock DirectoryLock::hold(const fs::path& dir, const char* name, LockKind kind) {
  const fs::path path = dir / name;
  const int fd =
      ::open(path.c_str(), (kind == LockKind::shared ? O_RDONLY : O_RDWR) | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0)
    throw UserError(fmt::format("cannot open '{}': {}", path.string(), std::strerror(errno)));
  DirectoryLock lock(fd);
  lock.dir_ = dir;
  lock.name_ = name;
  if (::flock(fd, (kind == LockKind::shared ? LOCK_SH : LOCK_EX) | LOCK_NB) != 0)
    refuse_in_use(dir, read_marker(dir, name).value_or(DirectoryMarker{}));
  if (kind == LockKind::exclusive) refuse_hard_linked_marker(path, fd);
  return lock;
}

void DirectoryLock::stamp(const std::string& header, int format) {
  const fs::path path = dir_ / name_;
  refuse_hard_linked_marker(path, fd_);
  const std::string text = fmt::format("{}\nformat = {}\nversion = {}\npid = {}\n", header, format,
                                       GRANSHOCK_VERSION_STRING, long(::getpid()));
  // Written over the old lines first, then cut to length: a write that fails (a full
  // disk) leaves the previous marker readable instead of an empty one.
  bool written = true;
  for (std::size_t done = 0; written && done < text.size();) {
    const ssize_t n = ::pwrite(fd_, text.data() + done, text.size() - done, off_t(done));
    written = n > 0 || (n < 0 && errno == EINTR);
    if (n > 0) done += std::size_t(n);
  }
  if (!written || ::ftruncate(fd_, off_t(text.size())) != 0 || ::fsync(fd_) != 0) {
    const int error = errno;
    if (created_) ::unlink(path.c_str());  // ours, created just now: the directory as it was
    throw UserError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(error)));
  }
}

DirectoryLock::DirectoryLock(DirectoryLock&& other) noexcept
    : fd_(other.fd_),
      dir_(std::move(other.dir_)),
      name_(std::move(other.name_)),
      created_(other.created_) {
  other.fd_ = -1;
}

DirectoryLock& DirectoryLock::operator=(DirectoryLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    dir_ = std::move(other.dir_);
    name_ = std::move(other.name_);
    created_ = other.created_;
    other.fd_ = -1;
  }
  return *this;
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the descriptor releases the flock
}

}  // namespace granshock

#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/user_error.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// Writes all of `contents` to fd; false (errno set) when a write fails.
bool write_all(int fd, const std::string& contents) {
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

std::string what_it_is(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISREG(mode)) return "a regular file";
  return "a special file";
}

}  // namespace

void remove_stale_temporary(const fs::path& tmp) {
  struct stat st {};
  if (::lstat(tmp.c_str(), &st) != 0) return;  // absent (or unreadable: the create says why)
  if (!S_ISREG(st.st_mode))
    throw UserError("'" + tmp.string() + "' is " + what_it_is(st.st_mode) +
                    "; granshock writes only files it creates itself: remove it");
  if (::unlink(tmp.c_str()) != 0 && errno != ENOENT)
    throw UserError("cannot remove the stale temporary '" + tmp.string() +
                    "': " + std::strerror(errno));
}

void write_file_atomically(const fs::path& path, const std::string& contents) {
  write_file_atomically(path, [&](const AtomicWrite& write) { write(contents); });
}

void write_file_atomically(const fs::path& path,
                           const std::function<void(const AtomicWrite&)>& produce) {
  const fs::path tmp = path.string() + ".tmp";
  remove_stale_temporary(tmp);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0)
    throw UserError("cannot write '" + path.string() + "': " + std::strerror(errno) +
                    (errno == EEXIST ? " (its temporary appeared meanwhile)" : ""));
  bool written = true;
  int write_errno = 0;
  try {
    produce([&](const std::string& piece) {
      if (written && !write_all(fd, piece)) {
        written = false;
        write_errno = errno;
      }
    });
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    ::unlink(tmp.c_str());
    throw UserError("writing '" + path.string() +
                    "' failed: " + std::strerror(written ? errno : write_errno));
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    ::unlink(tmp.c_str());
    throw UserError("cannot replace '" + path.string() + "': " + ec.message());
  }
}

void make_real_directory(const fs::path& dir) {
  if (::mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
    throw UserError("cannot create '" + dir.string() + "': " + std::strerror(errno));
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0)
    throw UserError("cannot create '" + dir.string() + "': " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode))
    throw UserError("'" + dir.string() + "' is " + what_it_is(st.st_mode) +
                    " where granshock writes a directory of its own: remove it");
}

}  // namespace granshock

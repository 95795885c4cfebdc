#include "io/regular_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/quoted_input.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a plain file";
}

// A path as a message shows it: on one line.
std::string one_line(const std::string& text) {
  return printable_line(text, 1024);
}

}  // namespace

RegularFile::RegularFile(const std::filesystem::path& path, const std::string& what, Links links)
    : where_(what + " '" + one_line(path.string()) + "'") {
  const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | (links == Links::refuse ? O_NOFOLLOW : 0);
  fd_ = ::open(path.c_str(), flags);
  if (fd_ < 0) {
    const int error = errno;
    if (error == ENOENT) throw UserError("cannot read " + where_ + ": no such file");
    if (error == ELOOP && links == Links::refuse)
      throw UserError(where_ + " is a symbolic link, not a regular file");
    throw UserError("cannot read " + where_ + ": " + std::strerror(error));
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int error = errno;
    close_now();
    throw UserError("cannot read " + where_ + ": " + std::strerror(error));
  }
  if (!S_ISREG(info.st_mode)) {
    close_now();
    throw UserError(where_ + " is " + kind_of(info.st_mode) + ", not a regular file");
  }
  // Reads of a regular file never block; clear the flag all the same for whoever reads.
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

RegularFile::~RegularFile() {
  close_now();
}

void RegularFile::close_now() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::string RegularFile::read_all(std::size_t max_bytes) const {
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd_, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw UserError("cannot read " + where_ + ": " + std::strerror(errno));
    if (got == 0) return text;
    text.append(buffer, std::size_t(got));
    if (text.size() > max_bytes)
      throw UserError(where_ + " is longer than " + std::to_string(max_bytes) + " bytes");
  }
}

void require_regular_file(const std::filesystem::path& path, const std::string& what, Links links) {
  const RegularFile file(path, what, links);
}

std::string read_regular_file(const std::filesystem::path& path, const std::string& what,
                              std::size_t max_bytes, Links links) {
  return RegularFile(path, what, links).read_all(max_bytes);
}

}  // namespace granshock

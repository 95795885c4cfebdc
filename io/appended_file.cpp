#include "io/appended_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>

#include "core/user_error.hpp"
#include "io/marked_directory.hpp"

namespace granshock {

AppendedFile::~AppendedFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendedFile::open(const std::filesystem::path& path) {
  if (fd_ >= 0) return;
  path_ = path;
  // O_NOFOLLOW: never through a link planted under the name (the run directory's check
  // refused one already; this closes the gap since).
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw UserError(fmt::format("cannot write '{}': {}", path_.string(), std::strerror(errno)));
  // Nor into a file with a second name (a hard link made since the check).
  struct stat st {};
  const bool known = ::fstat(fd_, &st) == 0;
  if (known && st.st_nlink > 1) {
    ::close(fd_);
    fd_ = -1;
    refuse_hard_link(path_, st.st_nlink);
  }
  was_empty_ = known && st.st_size == 0;
}

void AppendedFile::append(const std::string& text) {
  if (fd_ < 0 || failed_) return;
  const ssize_t n = ::write(fd_, text.data(), text.size());
  if (n == ssize_t(text.size())) return;
  failed_ = true;
  std::cerr << fmt::format(
      "granshock: warning: writing '{}' failed ({}); the run goes on without {}\n", path_.string(),
      n < 0 ? std::strerror(errno) : "a short write", lost_);
}

}  // namespace granshock

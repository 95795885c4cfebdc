#include "io/file_room.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace granshock {

int reserve_file_bytes(const std::filesystem::path& path, std::uintmax_t from, std::uintmax_t to) {
  if (to <= from) return 0;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return errno;
  // posix_fallocate returns the error itself. Where the file system cannot allocate
  // (EOPNOTSUPP), glibc writes one zero byte per block instead, and only where the byte
  // read there is zero, so no byte of the file changes.
  const int status = ::posix_fallocate(fd, off_t(from), off_t(to - from));
  ::close(fd);
  return status;
}

int trim_file(const std::filesystem::path& path, std::uintmax_t size) {
  if (file_bytes(path) <= size) return 0;
  return ::truncate(path.c_str(), off_t(size)) == 0 ? 0 : errno;
}

std::uintmax_t file_bytes(const std::filesystem::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? std::uintmax_t(st.st_size) : 0;
}

}  // namespace granshock

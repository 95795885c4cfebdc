// Input files are read only when they are regular files. A FIFO blocks the open (no
// writer) or the read (no data) forever, a character device such as /dev/zero never ends,
// and a directory or socket holds no file at all. The file is opened without blocking
// (O_NONBLOCK) and the descriptor itself is checked with fstat, so that nothing swapped in
// between a check and the open is read. Every refusal is one UserError naming what the
// file is for and what it is ("scene file 'x.toml' is a FIFO (named pipe), not a regular
// file"). Files a library opens by name (HDF5's run.h5 and checkpoint.h5) are checked with
// require_regular_file just before.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace granshock {

// Whether a symbolic link at the path itself is followed or refused (inside a run
// directory, where a link could lead granshock to read someone else's file).
enum class Links { follow, refuse };

// An open read-only descriptor of a regular file, closed with the object.
class RegularFile {
 public:
  // Throws UserError: "cannot read WHAT 'PATH': no such file", "WHAT 'PATH' is a
  // directory, not a regular file", and so on.
  RegularFile(const std::filesystem::path& path, const std::string& what,
              Links links = Links::follow);
  ~RegularFile();
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  int fd() const { return fd_; }
  // Reads the whole file; one byte more than max_bytes is refused ("WHAT 'PATH' is longer
  // than N bytes").
  std::string read_all(std::size_t max_bytes) const;

 private:
  void close_now();
  int fd_ = -1;
  std::string where_;  // "WHAT 'PATH'", for messages
};

// Checks that `path` is a regular file (opened as RegularFile, then closed).
void require_regular_file(const std::filesystem::path& path, const std::string& what,
                          Links links = Links::follow);

// The text of a regular file of at most max_bytes.
std::string read_regular_file(const std::filesystem::path& path, const std::string& what,
                              std::size_t max_bytes, Links links = Links::follow);

}  // namespace granshock

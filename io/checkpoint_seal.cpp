#include "io/checkpoint_seal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/user_error.hpp"
#include "io/file_hash.hpp"
#include "io/regular_file.hpp"

namespace granshock::seal {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[] = "granshock checkpoint\n";
constexpr char kHdf5Signature[] = "\x89HDF\r\n\x1a\n";
constexpr std::size_t kSignatureBytes = 8;

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

// Lines 1-4 (magic, version, length, hash); line 5 hashes them, so that every byte of
// the header is covered by some hash and a damaged version line is not misread.
std::string body(int format_version, std::uint64_t hashed_bytes, std::uint64_t hash) {
  return std::string(kMagic) + "format_version " + std::to_string(format_version) +
         "\nhashed_bytes " + std::to_string(hashed_bytes) + "\nhash " + hex(hash) + "\n";
}

std::string damaged(const fs::path& file, const std::string& cause) {
  return "checkpoint '" + file.string() + "' is damaged (" + cause +
         "): it cannot be resumed; rerun with --overwrite";
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// Reads up to `size` bytes at `offset`; fewer at the end of the file.
std::string read_at(int fd, std::uint64_t offset, std::size_t size) {
  std::string out(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t got = ::pread(fd, out.data() + done, size - done, off_t(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw std::runtime_error(std::strerror(errno));
    if (got == 0) break;
    done += std::size_t(got);
  }
  out.resize(done);
  return out;
}

struct Header {
  int version = 0;
  std::uint64_t hashed_bytes = 0;
  std::uint64_t hash = 0;
};

// `text` must be exactly key + " " + a number (decimal, or 16 hex digits for "hash").
template <class T>
bool field(const std::string& line, const std::string& key, T& value, int base = 10) {
  if (!starts_with(line, key + " ")) return false;
  const char* first = line.data() + key.size() + 1;
  const char* last = line.data() + line.size();
  const auto [end, error] = std::from_chars(first, last, value, base);
  return error == std::errc() && end == last && first != last;
}

enum class Parsed { broken, version_only, complete };

// Parses a header whose first line is the magic. The version is the second line in
// every format; a header whose self-hash holds but whose later lines are not this
// layout gives version_only (a format this granshock does not know).
Parsed parse(const std::string& block, Header& h) {
  const std::string text = block.substr(0, block.find('\0'));
  if (block.find_first_not_of('\0', text.size()) != std::string::npos) return Parsed::broken;
  const std::size_t last = text.rfind("header_hash ");
  if (last == std::string::npos || last == 0 || text[last - 1] != '\n') return Parsed::broken;
  if (text.compare(last, std::string::npos,
                   "header_hash " + hex(hash_bytes(text.data(), last)) + "\n") != 0)
    return Parsed::broken;
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < last;) {
    const std::size_t eol = text.find('\n', at);
    lines.push_back(text.substr(at, eol - at));
    at = eol + 1;
  }
  if (lines.size() < 2 || !field(lines[1], "format_version", h.version)) return Parsed::broken;
  const bool complete = lines.size() == 4 && field(lines[2], "hashed_bytes", h.hashed_bytes) &&
                        field(lines[3], "hash", h.hash, 16) &&
                        text.substr(0, last) == body(h.version, h.hashed_bytes, h.hash);
  return complete ? Parsed::complete : Parsed::version_only;
}

// "3 to 4", or "4" where one version is read.
std::string versions(int oldest, int newest) {
  return oldest == newest ? std::to_string(newest)
                          : std::to_string(oldest) + " to " + std::to_string(newest);
}

}  // namespace

std::string header(int format_version, std::uint64_t hashed_bytes, std::uint64_t hash) {
  std::string text = body(format_version, hashed_bytes, hash);
  text += "header_hash " + hex(hash_bytes(text.data(), text.size())) + "\n";
  if (text.size() > kUserBlockBytes) throw std::logic_error("checkpoint header too long");
  text.resize(kUserBlockBytes, '\0');
  return text;
}

void seal_file(const fs::path& file, int format_version) {
  const std::uintmax_t size = fs::file_size(file);
  if (size < kUserBlockBytes) throw std::runtime_error("the file has no user block");
  const std::uint64_t hash = hash_file_from(file, kUserBlockBytes);
  const std::string block = header(format_version, size - kUserBlockBytes, hash);
  const int fd = ::open(file.c_str(), O_WRONLY);
  if (fd < 0) throw std::runtime_error(std::strerror(errno));
  const ssize_t put = ::pwrite(fd, block.data(), block.size(), 0);
  const int saved = errno;
  ::close(fd);
  if (put != ssize_t(block.size()))
    throw std::runtime_error(put < 0 ? std::strerror(saved) : "short write");
}

int verify_file(const fs::path& file, int oldest, int newest) {
  const std::string where = "checkpoint '" + file.string() + "'";
  const RegularFile opened(file, "checkpoint");  // a FIFO would block the reads forever
  const int fd = opened.fd();
  std::string block, signature;
  std::uint64_t size = 0;
  try {
    block = read_at(fd, 0, kUserBlockBytes);
    signature = read_at(fd, kUserBlockBytes, kSignatureBytes);
    struct stat info {};
    if (::fstat(fd, &info) != 0) throw std::runtime_error(std::strerror(errno));
    size = std::uint64_t(info.st_size);
  } catch (const std::runtime_error& e) {
    throw UserError("cannot read " + where + ": " + e.what());
  }

  const std::string hdf5(kHdf5Signature, kSignatureBytes);
  if (size == 0) throw UserError("cannot read " + where + ": the file is empty");
  if (!starts_with(block, kMagic)) {
    if (signature == hdf5) throw UserError(damaged(file, "checksum header unreadable"));
    if (starts_with(block, hdf5))
      throw UserError("cannot read " + where +
                      ": it has no checksum header, so it is a checkpoint of format version 1 "
                      "(this granshock reads format versions " +
                      versions(oldest, newest) +
                      ") or not a granshock checkpoint at all; rerun with --overwrite");
    throw UserError("cannot read " + where + ": not a granshock checkpoint");
  }
  Header h;
  const Parsed parsed = block.size() < kUserBlockBytes ? Parsed::broken : parse(block, h);
  if (parsed == Parsed::broken) throw UserError(damaged(file, "checksum header unreadable"));
  if (h.version < oldest || h.version > newest)
    throw UserError(where + " has format version " + std::to_string(h.version) +
                    "; this granshock reads format versions " + versions(oldest, newest) +
                    ": resume it with the granshock that wrote it, or rerun with --overwrite");
  if (parsed != Parsed::complete) throw UserError(damaged(file, "checksum header unreadable"));
  if (size - kUserBlockBytes != h.hashed_bytes)
    throw UserError(damaged(file, std::to_string(size - kUserBlockBytes) +
                                      " bytes after the header, which says " +
                                      std::to_string(h.hashed_bytes) + ": truncated or extended"));
  std::uint64_t hash = 0;
  try {
    hash = hash_file_from(file, kUserBlockBytes);
  } catch (const std::runtime_error& e) {
    throw UserError("cannot read " + where + ": " + e.what());
  }
  if (hash != h.hash) throw UserError(damaged(file, "checksum mismatch"));
  return h.version;
}

}  // namespace granshock::seal

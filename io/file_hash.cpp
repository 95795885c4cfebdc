#include "io/file_hash.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace granshock {

namespace {

// The construction: the input is read as little-endian 64-bit words in stripes of four;
// each of four independent lanes takes one word per stripe,
//   lane = rotl(lane + word * K2, 31) * K1,
// (the accumulation round of xxHash64: the lanes' multiplies do not depend on each
// other, so they overlap in the pipeline and the loop runs at several GB/s). The last
// partial stripe is zero-padded to whole words, each folded into the merged lanes; the
// byte length is mixed in, which tells zero padding from real zero bytes; a final
// avalanche (MurmurHash3's fmix64) makes every input bit affect every output bit.
constexpr std::uint64_t kK1 = 0x9e3779b185ebca87ULL;
constexpr std::uint64_t kK2 = 0xc2b2ae3d27d4eb4fULL;
constexpr std::uint64_t kK3 = 0x165667b19e3779f9ULL;

inline std::uint64_t rotl(std::uint64_t x, int r) {
  return (x << r) | (x >> (64 - r));
}

inline std::uint64_t load_le(const unsigned char* p) {
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  w = __builtin_bswap64(w);
#endif
  return w;
}

inline std::uint64_t round(std::uint64_t lane, std::uint64_t word) {
  return rotl(lane + word * kK2, 31) * kK1;
}

inline void stripe(std::uint64_t (&lanes)[4], const unsigned char* p) {
  lanes[0] = round(lanes[0], load_le(p));
  lanes[1] = round(lanes[1], load_le(p + 8));
  lanes[2] = round(lanes[2], load_le(p + 16));
  lanes[3] = round(lanes[3], load_le(p + 24));
}

}  // namespace

void FileHash64::update(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  length_ += size;
  if (pending_ > 0) {
    const std::size_t take = std::min(size, sizeof stripe_ - pending_);
    std::memcpy(stripe_ + pending_, p, take);
    pending_ += take;
    p += take;
    size -= take;
    if (pending_ < sizeof stripe_) return;
    stripe(lanes_, stripe_);
    pending_ = 0;
  }
  for (; size >= sizeof stripe_; p += sizeof stripe_, size -= sizeof stripe_) stripe(lanes_, p);
  std::memcpy(stripe_, p, size);
  pending_ = size;
}

std::uint64_t FileHash64::digest() const {
  std::uint64_t h =
      rotl(lanes_[0], 1) + rotl(lanes_[1], 7) + rotl(lanes_[2], 12) + rotl(lanes_[3], 18);
  unsigned char tail[32] = {};
  std::memcpy(tail, stripe_, pending_);
  for (std::size_t at = 0; at < pending_; at += 8)
    h = rotl(h ^ round(0, load_le(tail + at)), 27) * kK1 + kK3;
  h ^= length_ * kK3;
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

std::uint64_t hash_bytes(const void* data, std::size_t size) {
  FileHash64 h;
  h.update(data, size);
  return h.digest();
}

std::uint64_t hash_file_from(const std::filesystem::path& file, std::uint64_t offset) {
  const int fd = ::open(file.c_str(), O_RDONLY);
  if (fd < 0) throw std::runtime_error(std::strerror(errno));
  FileHash64 h;
  // 128 KiB: stays in the L2 cache between read() and hashing (measured faster than
  // 1 MiB buffers or mmap for a 33 MB checkpoint).
  std::vector<unsigned char> buffer(std::size_t{1} << 17);
  off_t at = static_cast<off_t>(offset);
  for (;;) {
    const ssize_t got = ::pread(fd, buffer.data(), buffer.size(), at);
    if (got < 0) {
      if (errno == EINTR) continue;
      const std::string reason = std::strerror(errno);
      ::close(fd);
      throw std::runtime_error(reason);
    }
    if (got == 0) break;
    h.update(buffer.data(), static_cast<std::size_t>(got));
    at += got;
  }
  ::close(fd);
  return h.digest();
}

}  // namespace granshock

// gshash64: the 64-bit checksum of checkpoint files (docs/output_format.md). It detects
// accidental damage (flipped bits, torn or truncated writes), not deliberate edits:
// it is not a cryptographic hash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace granshock {

// Streaming form: update() with any split of the input gives the digest of the whole.
class FileHash64 {
 public:
  void update(const void* data, std::size_t size);
  std::uint64_t digest() const;

 private:
  // xxHash64's starting lanes for seed 0: K1 + K2, K2, 0, -K1 (file_hash.cpp).
  std::uint64_t lanes_[4] = {0x60ea27eeadc0b5d6ULL, 0xc2b2ae3d27d4eb4fULL, 0ULL,
                             0x61c8864e7a143579ULL};
  unsigned char stripe_[32] = {};
  std::size_t pending_ = 0;  // bytes in stripe_
  std::uint64_t length_ = 0;
};

std::uint64_t hash_bytes(const void* data, std::size_t size);

// The hash of bytes [offset, end of file); throws std::runtime_error when the file
// cannot be read.
std::uint64_t hash_file_from(const std::filesystem::path& file, std::uint64_t offset);

}  // namespace granshock

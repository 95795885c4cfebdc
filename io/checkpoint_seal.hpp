// The checksum header of checkpoint.h5 (layout: docs/output_format.md). HDF5 leaves the
// first 512 bytes of the file (its user block) to the application; the header there
// holds the format version, the length and the hash of every byte after it. It is
// checked before HDF5 sees the file, so a damaged superblock or B-tree never reaches a
// library that may crash on bad metadata.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace granshock::seal {

constexpr std::uint64_t kUserBlockBytes = 512;

// The header for `hashed_bytes` bytes with hash `hash` (ASCII, NUL-padded to the block).
std::string header(int format_version, std::uint64_t hashed_bytes, std::uint64_t hash);

// Hashes the closed file `file` after its user block and writes the header into it.
// Throws std::runtime_error when the file cannot be read or written.
void seal_file(const std::filesystem::path& file, int format_version);

// Checks the header, the file's length and its hash; returns the header's format version.
// Throws UserError with one line naming `file` and the cause: damaged, written in a format
// version outside [oldest, newest] (format 1 had no header), or not a granshock checkpoint
// at all.
int verify_file(const std::filesystem::path& file, int oldest, int newest);

}  // namespace granshock::seal

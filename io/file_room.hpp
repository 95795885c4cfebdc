// Room on disk for a file to grow into before it is written (docs/output_format.md, "A full
// disk"): run.h5 is changed in place by HDF5, and a write that fails half-way (no space, a
// file-size limit) can leave it unreadable. Reserving the bytes an append can take first
// turns a full disk into a refusal before anything is written.
#pragma once

#include <cstdint>
#include <filesystem>

namespace granshock {

// Allocates the bytes [from, to) of the file at `path` on disk (posix_fallocate; a shorter
// file grows to `to`), so that writes there cannot fail for want of space or because of a
// file-size limit. Returns 0, or the errno that refused it (ENOSPC, EFBIG, ...); bytes the
// file held before are never changed.
int reserve_file_bytes(const std::filesystem::path& path, std::uintmax_t from, std::uintmax_t to);

// Cuts the file at `path` to `size` bytes when it is longer (a reservation left unused).
// Returns 0 or the errno of the failure.
int trim_file(const std::filesystem::path& path, std::uintmax_t size);

// The file's size in bytes, or 0 when it cannot be read.
std::uintmax_t file_bytes(const std::filesystem::path& path);

}  // namespace granshock

// Opening an existing granshock HDF5 file (run.h5, checkpoint.h5) for reading or writing:
// each refusal is one UserError line, "cannot DOING 'PATH': REASON".
#pragma once

#include <hdf5.h>

#include <filesystem>
#include <string>

#include "core/user_error.hpp"
#include "io/hdf5_handle.hpp"

namespace granshock::h5 {

// "cannot DOING 'PATH': REASON" ("cannot resume 'out/run.h5': no such file").
UserError cannot_open(const std::string& doing, const std::filesystem::path& path,
                      const std::string& reason);

// Silences HDF5's error printing, and refuses ("no such file") when nothing is at `path`.
void require_existing(const std::filesystem::path& path, const std::string& doing);

// H5Fopen with `flags` (H5F_ACC_RDONLY, H5F_ACC_RDWR); refused with HDF5's reason.
Handle open_existing_file(const std::filesystem::path& path, unsigned flags,
                          const std::string& doing);

// Whether the file's root attribute granshock_file is `kind` ("run", "checkpoint"). Throws
// Hdf5Error when it cannot be read.
bool is_granshock_file(hid_t file, const std::string& kind);

}  // namespace granshock::h5

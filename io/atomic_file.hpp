// Writing a file so that readers never see half of it: write to a temporary name in the
// same directory, then rename over the target (atomic on POSIX file systems).
#pragma once

#include <filesystem>
#include <string>

namespace granshock {

// Throws UserError naming the path when the directory is not writable.
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

}  // namespace granshock

#include "run_directory.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include "user_error.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {
// The nearest existing ancestor must be a writable directory for create_directories.
void check_creatable(const fs::path& dir) {
  fs::path probe = fs::absolute(dir);
  while (!probe.empty() && !fs::exists(probe)) probe = probe.parent_path();
  if (!fs::is_directory(probe))
    throw UserError(fmt::format("output directory '{}': '{}' is not a directory", dir.string(),
                                probe.string()));
  if (access(probe.c_str(), W_OK | X_OK) != 0)
    throw UserError(
        fmt::format("output directory '{}': '{}' is not writable", dir.string(), probe.string()));
}
}  // namespace

void check_run_directory(const fs::path& dir, DirectoryMode mode) {
  const bool exists = fs::exists(dir);
  if (exists && !fs::is_directory(dir))
    throw UserError(
        fmt::format("output directory '{}' exists and is not a directory", dir.string()));
  if (mode == DirectoryMode::resume) {
    if (!fs::exists(dir / "checkpoint.h5") || !fs::exists(dir / "run.h5"))
      throw UserError(fmt::format("--resume: '{}' holds no checkpoint.h5 and run.h5 to resume from",
                                  dir.string()));
    if (access(dir.c_str(), W_OK | X_OK) != 0)
      throw UserError(fmt::format("output directory '{}' is not writable", dir.string()));
    return;
  }
  if (exists && !fs::is_empty(dir) && mode != DirectoryMode::overwrite)
    throw UserError(
        fmt::format("output directory '{}' already holds a run; use --overwrite to replace it "
                    "or --resume to continue it",
                    dir.string()));
  if (exists) {
    if (access(dir.c_str(), W_OK | X_OK) != 0)
      throw UserError(fmt::format("output directory '{}' is not writable", dir.string()));
  } else {
    check_creatable(dir);
  }
}

void prepare_run_directory(const fs::path& dir, DirectoryMode mode) {
  if (mode == DirectoryMode::overwrite && fs::exists(dir))
    for (const auto& entry : fs::directory_iterator(dir)) fs::remove_all(entry.path());
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw UserError(
        fmt::format("cannot create output directory '{}': {}", dir.string(), ec.message()));
}

}  // namespace granshock

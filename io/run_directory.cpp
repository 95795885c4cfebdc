#include "io/run_directory.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <stdexcept>

#include "core/user_error.hpp"
#include "io/fields_directory.hpp"

namespace granshock {

namespace fs = std::filesystem;

const std::vector<std::string>& run_outputs() {
  // run.h5 (io/run_file.cpp), its XDMF (io/xdmf_writer.cpp), the checkpoint, the log
  // (cases/bow_shock/run_log.hpp) and the thermo table (cases/bow_shock/thermo_table.hpp); the
  // summary (cases/bow_shock/bow_shock_run.cpp) is among the field analysis' outputs, which a run
  // writes at its end. Atomic writers use NAME.tmp.
  static const std::vector<std::string> outputs = [] {
    std::vector<std::string> all = {"run.h5",        "run.xmf",           "run.xmf.tmp",
                                    "checkpoint.h5", "checkpoint.h5.tmp", "log.txt",
                                    "thermo.txt"};
    all.insert(all.end(), fields_outputs().begin(), fields_outputs().end());
    return all;
  }();
  return outputs;
}

namespace {

bool is_temporary(const std::string& name) {
  return name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0;
}

void refuse_unmarked(const fs::path& dir, DirectoryMode mode) {
  if (mode == DirectoryMode::fields)
    throw UserError(fmt::format(
        "'{}' is not a granshock run directory (it has no {} marker); granshock writes the "
        "analysis into a run directory only where it marked it: write it into a new directory "
        "with --out",
        dir.string(), kRunMarker));
  std::error_code ec;
  const bool old_run = fs::exists(dir / "run.h5", ec) || fs::exists(dir / "checkpoint.h5", ec);
  throw UserError(fmt::format(
      "output directory '{}' is not empty and is not a granshock run directory (it has no "
      "{} marker){}; granshock never deletes or resumes files it did not create: choose a "
      "new or empty directory with --out",
      dir.string(), kRunMarker,
      old_run ? ", though it holds run files, perhaps from a granshock before 0.2 that did not "
                "mark its directories: move them away yourself"
              : ""));
}

}  // namespace

void RunDirectory::check(const fs::path& dir, DirectoryMode mode) {
  if (dir.empty()) throw UserError("the output directory name is empty");
  std::error_code ec;
  const bool exists = fs::exists(dir, ec);
  if (exists && !fs::is_directory(dir, ec))
    throw UserError(
        fmt::format("output directory '{}' exists and is not a directory", dir.string()));
  if (!exists) {
    if (mode == DirectoryMode::resume)
      throw UserError(fmt::format("--resume: output directory '{}' does not exist", dir.string()));
    if (mode == DirectoryMode::fields)
      throw UserError(fmt::format("run directory '{}' does not exist", dir.string()));
    check_creatable(dir);
    return;
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw UserError(fmt::format("output directory '{}' is not writable", dir.string()));

  // Emptiness first, the marker second: a claim of the directory meanwhile creates its
  // marker before anything else, so a directory found not empty shows the marker to the
  // read after (the loser of a race for a new directory is told "in use", not "unmarked").
  const bool empty = directory_is_empty(dir);
  const std::optional<DirectoryMarker> marker = read_marker(dir, kRunMarker);
  // Empty, or holding only the empty marker of a claim that wrote nothing else.
  if (!marker || holds_only_an_empty_marker(dir, kRunMarker)) {
    if (mode == DirectoryMode::fields || !(empty || marker)) refuse_unmarked(dir, mode);
    if (marker && locked_by_another(dir, kRunMarker)) refuse_in_use(dir, *marker);
    if (mode == DirectoryMode::resume)
      throw UserError(
          fmt::format("--resume: '{}' is empty; there is no run to resume", dir.string()));
    return;  // an empty directory is claimed as it is
  }
  check_marker_format(dir, *marker, kRunDirectoryFormat, "run-directory");
  if (locked_by_another(dir, kRunMarker)) refuse_in_use(dir, *marker);
  check_outputs_are_files(dir, run_outputs());
  if (mode == DirectoryMode::create)
    throw UserError(fmt::format(
        "output directory '{}' already holds a granshock run; use --overwrite to replace its "
        "files or --resume to continue it",
        dir.string()));
  if (mode == DirectoryMode::resume && !fs::exists(dir / "checkpoint.h5", ec) &&
      fs::exists(dir / "run.h5", ec))
    throw UserError(fmt::format(
        "--resume: '{}' holds run.h5 but no checkpoint.h5: the run was stopped before its "
        "first checkpoint; start again with --overwrite",
        dir.string()));
  if (mode == DirectoryMode::resume &&
      (!fs::exists(dir / "checkpoint.h5", ec) || !fs::exists(dir / "run.h5", ec)))
    throw UserError(fmt::format("--resume: '{}' holds no checkpoint.h5 and run.h5 to resume from",
                                dir.string()));
}

namespace {

constexpr const char* kRunMarkerHeader =
    "granshock run directory: granshock removes only its own outputs here";

}  // namespace

std::optional<DirectoryLock> hold_for_reading(const fs::path& dir) {
  const std::optional<DirectoryMarker> marker = read_marker(dir, kRunMarker);
  if (!marker) return std::nullopt;
  if (locked_for_writing(dir, kRunMarker))
    throw UserError(fmt::format(
        "run directory '{}' is in use by another granshock run{}; wait for it to end, then try "
        "again",
        dir.string(), marker->pid > 0 ? fmt::format(" (pid {})", marker->pid) : ""));
  return DirectoryLock::hold(dir, kRunMarker, LockKind::shared);
}

RunDirectory RunDirectory::claim(const fs::path& dir, DirectoryMode mode) {
  if (mode == DirectoryMode::resume || mode == DirectoryMode::fields) {
    RunDirectory held = hold(dir, mode);
    held.settle();
    return held;
  }
  check(dir, mode);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec)
    throw UserError(
        fmt::format("cannot create output directory '{}': {}", dir.string(), ec.message()));
  RunDirectory claimed(dir, mode,
                       DirectoryLock::take(dir, kRunMarker, kRunMarkerHeader, kRunDirectoryFormat));
  // The lock is ours now: check the outputs again (check() looked before we held it),
  // then remove, so that a refusal comes before any file is gone.
  check_outputs_are_files(dir, run_outputs());
  claimed.clean();
  claimed.settled_ = true;
  return claimed;
}

RunDirectory RunDirectory::hold(const fs::path& dir, DirectoryMode mode) {
  if (mode != DirectoryMode::resume && mode != DirectoryMode::fields)
    throw std::logic_error("RunDirectory::hold: a directory to resume or analyse only");
  check(dir, mode);
  RunDirectory held(dir, mode, DirectoryLock::hold(dir, kRunMarker, LockKind::exclusive));
  check_outputs_are_files(dir, run_outputs());  // again, now that the lock is ours
  return held;
}

void RunDirectory::settle() {
  if (settled_) return;
  lock_.stamp(kRunMarkerHeader, kRunDirectoryFormat);
  clean();
  settled_ = true;
}

void RunDirectory::clean() {
  if (mode_ == DirectoryMode::overwrite) remove_outputs(dir_, run_outputs());
  if (mode_ == DirectoryMode::resume) {  // temporaries left by a killed run
    std::vector<std::string> temporaries;
    for (const std::string& name : run_outputs())
      if (is_temporary(name)) temporaries.push_back(name);
    remove_outputs(dir_, temporaries);
  }
}

}  // namespace granshock

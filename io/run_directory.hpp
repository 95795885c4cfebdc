// The run directory of `granshock run` and who owns it (docs/output_format.md, "The run
// directory"). A directory becomes a run directory when granshock writes its marker file
// into it, before anything else; only a marked directory is ever cleaned, resumed or
// analysed in place, and cleaning removes only the files a run writes (run_outputs()),
// never a user's files. A run, and `granshock fields` in a run directory, hold an
// exclusive lock on the marker while they write, so a second one is refused instead of
// interleaving its writes.
//
// Checking and claiming are separate steps so that a refused command writes nothing:
// check() only looks; claim() creates, marks, locks and cleans once it has been accepted.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/marked_directory.hpp"

namespace granshock {

// create, overwrite, resume: `granshock run` without a flag, with --overwrite, with
// --resume. fields: `granshock fields DIR`, which writes the analysis of DIR/run.h5 into
// the run directory DIR itself.
enum class DirectoryMode { create, overwrite, resume, fields };

// The layout version of run directories this granshock writes and reads.
inline constexpr int kRunDirectoryFormat = 1;

// Every path (relative to the run directory) that `granshock run` and `granshock fields`
// write into a run directory, temporaries included; `--overwrite` removes these and
// nothing else.
const std::vector<std::string>& run_outputs();

// A run directory that is only read (`fields DIR --out OUT`, `export`): refused while a run
// or `fields DIR` writes it, naming the holder's pid, then held with a shared lock until the
// object goes, so that no run starts writing it meanwhile (other readers may share it).
// Nothing for a directory without a marker, which no run writes.
std::optional<DirectoryLock> hold_for_reading(const std::filesystem::path& dir);

class RunDirectory {
 public:
  // Throws UserError, with one line saying why and what to do, when the directory may not
  // be used in this mode: an unmarked directory that is not empty (for fields: any
  // unmarked directory), a marked one without --overwrite/--resume, a run directory of
  // another format, one locked by another granshock, --resume without a checkpoint, a
  // path that cannot be created or written, an output name that is a symbolic link, a
  // directory or a special file. Creates and changes nothing.
  static void check(const std::filesystem::path& dir, DirectoryMode mode);

  // Checks again, then creates the directory if needed, writes the marker, takes the
  // lock and (overwrite) removes the previous run's files or (resume) stale temporaries.
  static RunDirectory claim(const std::filesystem::path& dir, DirectoryMode mode);

  // resume, fields: checks again and takes the lock, writing and removing nothing, so
  // that the command holds the directory from its first read (no run can replace run.h5
  // under `fields`) and a refusal found while reading leaves it as it was. settle() then
  // does the rest of claim(): the marker's lines, the stale temporaries.
  static RunDirectory hold(const std::filesystem::path& dir, DirectoryMode mode);
  void settle();

  const std::filesystem::path& path() const { return dir_; }

 private:
  RunDirectory(std::filesystem::path dir, DirectoryMode mode, DirectoryLock lock)
      : dir_(std::move(dir)), mode_(mode), lock_(std::move(lock)) {}
  void clean();  // claim()'s removals of this mode
  std::filesystem::path dir_;
  DirectoryMode mode_;
  DirectoryLock lock_;  // released with the object
  bool settled_ = false;
};

}  // namespace granshock

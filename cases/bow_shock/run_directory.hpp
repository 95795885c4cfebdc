// The run directory of `granshock run` and who owns it (docs/output_format.md, "The run
// directory"). A directory becomes a run directory when granshock writes its marker file
// into it, before anything else; only a marked directory is ever cleaned or resumed, and
// cleaning removes only the files a run writes (run_outputs()), never a user's files.
// A run holds an exclusive lock on the marker for its whole duration, so a second run
// into the same directory is refused instead of interleaving its writes.
//
// Checking and claiming are separate steps so that a refused run writes nothing: check()
// only looks; claim() creates, marks, locks and cleans once the run has been accepted.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace granshock {

enum class DirectoryMode { create, overwrite, resume };

// The marker's file name inside a run directory.
inline constexpr const char* kRunMarker = ".granshock-run";
// The layout version of run directories this granshock writes and reads.
inline constexpr int kRunDirectoryFormat = 1;

// Every path (relative to the run directory) that `granshock run` and `granshock fields`
// write into a run directory, temporaries included; `--overwrite` removes these and
// nothing else.
const std::vector<std::string>& run_outputs();

class RunDirectory {
 public:
  // Throws UserError, with one line saying why and what to do, when the directory may not
  // be used in this mode: an unmarked directory that is not empty, a marked one without
  // --overwrite/--resume, a run directory of another format, one locked by a running
  // granshock, --resume without a checkpoint, a path that cannot be created or written,
  // an output name that is a symbolic link. Creates and changes nothing.
  static void check(const std::filesystem::path& dir, DirectoryMode mode);

  // Checks again, then creates the directory if needed, writes the marker, takes the
  // lock and (overwrite) removes the previous run's files or (resume) stale temporaries.
  static RunDirectory claim(const std::filesystem::path& dir, DirectoryMode mode);

  RunDirectory(RunDirectory&& other) noexcept;
  RunDirectory& operator=(RunDirectory&& other) noexcept;
  RunDirectory(const RunDirectory&) = delete;
  RunDirectory& operator=(const RunDirectory&) = delete;
  ~RunDirectory();  // releases the lock

  const std::filesystem::path& path() const { return dir_; }

 private:
  RunDirectory(std::filesystem::path dir, int lock_fd) : dir_(std::move(dir)), lock_fd_(lock_fd) {}
  std::filesystem::path dir_;
  int lock_fd_ = -1;
};

}  // namespace granshock

// What a run says (docs/output_format.md, "log.txt"): every line it shows on stderr is also
// appended, after the wall-clock time, to log.txt in the run directory, and its warnings
// are kept for summary.json. Lines said before the run is accepted (the scene's warnings,
// the calibrations, the checks of the directory and of a checkpoint to resume) wait in
// memory and are written with their own times once it is; a refused run writes nothing.
//
// log.txt follows the run directory's rules (io/run_directory.hpp): it is one of the run's
// outputs (replaced by --overwrite, never written through a symbolic link), and it is only
// ever appended to, one whole line per write, so a run killed half-way leaves lines that
// --resume continues. A log that cannot be written (a full disk) is said once and the run
// goes on: the run's own files decide whether it can resume.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/appended_file.hpp"

namespace granshock {

class RunLog {
 public:
  // speaks: rank 0, which alone writes stderr and the log; the others keep nothing.
  explicit RunLog(bool speaks) : speaks_(speaks) {}
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  // A line on stderr and in the log.
  void say(const std::string& line);
  // "granshock: warning: MESSAGE", said, and kept for summary.json (once per message).
  void warn(const std::string& message);
  // A line in the log alone: one the program prints itself (the error that ends the run).
  void record(const std::string& line);
  // From now on lines go to DIR/log.txt (appended), beginning with those waiting.
  void open(const std::filesystem::path& dir);
  bool is_open() const { return file_.is_open(); }

  const std::vector<std::string>& warnings() const { return warnings_; }

  // The time stamp of a line: UTC, to the millisecond, e.g. 2026-11-26T18:49:03.123Z.
  static std::string now();

 private:
  bool speaks_;
  AppendedFile file_{"its log"};
  std::vector<std::string> pending_;  // stamped lines, before open()
  std::vector<std::string> warnings_;
};

}  // namespace granshock

// The directory that `granshock fields DIR... --out OUT` writes when OUT is not the run
// directory itself (docs/output_format.md, "The fields directory"). It follows the rules
// of the run directory (marked_directory.hpp): OUT is taken only when it is new, empty,
// or marked by granshock, its own marker (.granshock-fields) says that `granshock fields`
// made it, it is locked while written, and every output is a file granshock creates
// itself. A run directory is never an OUT: its analysis is written there by `granshock
// fields DIR` alone, under the run's lock. The comparison of several runs may also go
// into a study directory, where `granshock study` writes its own (docs/study.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/marked_directory.hpp"

namespace granshock {

// The layout version of fields directories this granshock writes and reads.
inline constexpr int kFieldsDirectoryFormat = 1;

// What OUT receives: the analysis of one run, or the comparison of several.
enum class FieldsOutput { one_run, comparison };

// Every path (relative to its directory) the analysis of one run writes: fields.h5,
// fields.xmf, detachment_convergence.csv, summary.json and the figures, temporaries
// included. A run directory holds them too (run_outputs()).
const std::vector<std::string>& fields_outputs();

// Every path the comparison of several runs writes: detachment.csv, detachment.json and
// figures/detachment_length.png, temporaries included.
const std::vector<std::string>& comparison_outputs();

class FieldsDirectory {
 public:
  // Throws UserError, with one line saying why and what to do, unless `out` may receive
  // `what`: it must be new, empty, or marked by `granshock fields` (of this format, not
  // locked by another granshock), or, for a comparison, a study directory; a run
  // directory and any other directory that is not empty are refused, and so is an output
  // name that is a symbolic link, a directory or a special file. Changes nothing.
  static void check(const std::filesystem::path& out, FieldsOutput what);

  // Checks again, then creates the directory if needed, writes the marker and takes the
  // lock (a study directory is written under the study's own rules: no marker, no lock).
  static FieldsDirectory claim(const std::filesystem::path& out, FieldsOutput what);

  const std::filesystem::path& path() const { return dir_; }

 private:
  FieldsDirectory(std::filesystem::path dir, DirectoryLock lock)
      : dir_(std::move(dir)), lock_(std::move(lock)) {}
  std::filesystem::path dir_;
  DirectoryLock lock_;
};

}  // namespace granshock

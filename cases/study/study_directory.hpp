// The directory of a study (docs/study.md, "The study directory"): one run directory per
// case and the study's tables. A marker file names the study that owns it, so that a
// directory is reused only by the same study, and a directory the user filled is never
// taken (as run directories, docs/output_format.md).
#pragma once

#include <filesystem>
#include <string>

#include "io/marked_directory.hpp"  // kStudyMarker

namespace granshock {

enum class StudyDirectoryState { absent, empty, this_study };

// Throws UserError with one line when `out` cannot hold the study `name`: not a directory,
// not empty and not marked, or marked for another study. Changes nothing.
StudyDirectoryState check_study_directory(const std::filesystem::path& out,
                                          const std::string& name);

// Checks, then creates `out` and its marker. Safe when several array tasks start at once:
// the marker appears whole or not at all, and a task that finds it compares its study name.
void claim_study_directory(const std::filesystem::path& out, const std::string& name);

}  // namespace granshock

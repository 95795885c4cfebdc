#include "cases/study/study_directory.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/user_error.hpp"
#include "io/atomic_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// The study named by the marker of `out` ("" when the marker names none).
std::string marked_study(const fs::path& out) {
  std::ifstream in(out / kStudyMarker);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string key, eq, value;
    if (fields >> key >> eq >> value && key == "study" && eq == "=") return value;
  }
  return {};
}

void check_marker(const fs::path& out, const std::string& name) {
  const fs::path marker = out / kStudyMarker;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(marker, ec)))
    throw UserError(fmt::format("'{}' is not a regular file; it cannot mark a study directory",
                                marker.string()));
  const std::string owner = marked_study(out);
  if (owner != name)
    throw UserError(fmt::format(
        "'{}' holds the study '{}', not '{}'; a study directory is reused only by its own study: "
        "choose another --out",
        out.string(), owner.empty() ? "(unnamed)" : owner, name));
}

// Empty, apart from the marker another task is writing (claim_study_directory).
bool is_empty_directory(const fs::path& out) {
  std::error_code ec;
  const std::string temporary = std::string(kStudyMarker) + ".";
  for (const fs::directory_entry& e : fs::directory_iterator(out, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(temporary, 0) != 0 || name.size() < 4 ||
        name.compare(name.size() - 4, 4, ".tmp") != 0)
      return false;
  }
  return !ec;
}

std::string marker_text(const std::string& name) {
  return fmt::format(
      "granshock study directory: one run directory per case and the study's tables\n"
      "format = 1\nstudy = {}\n",
      name);
}

}  // namespace

StudyDirectoryState check_study_directory(const fs::path& out, const std::string& name) {
  std::error_code ec;
  if (!fs::exists(out, ec)) return StudyDirectoryState::absent;
  if (!fs::is_directory(out, ec))
    throw UserError(
        fmt::format("study directory '{}' exists and is not a directory", out.string()));
  // The listing first, the marker second: a task claiming the directory meanwhile
  // (claim_study_directory) links its marker before it makes anything else, so whatever
  // the listing saw beside temporaries, the marker is there by the second look.
  const bool empty = is_empty_directory(out);
  if (fs::exists(fs::symlink_status(out / kStudyMarker, ec))) {
    check_marker(out, name);
    return StudyDirectoryState::this_study;
  }
  if (empty) return StudyDirectoryState::empty;
  throw UserError(fmt::format(
      "study directory '{}' is not empty and holds no study (no {} marker); granshock never "
      "writes into a directory it did not create: choose a new or empty directory with --out",
      out.string(), kStudyMarker));
}

void claim_study_directory(const fs::path& out, const std::string& name) {
  if (check_study_directory(out, name) == StudyDirectoryState::this_study) return;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec)
    throw UserError(
        fmt::format("cannot create study directory '{}': {}", out.string(), ec.message()));
  // Written whole under a name of this process, then linked: link() fails when another
  // task made the marker first, and then that marker is checked instead.
  const fs::path own = out / fmt::format("{}.{}.tmp", kStudyMarker, long(::getpid()));
  write_file_atomically(own, marker_text(name));
  const int linked = ::link(own.c_str(), (out / kStudyMarker).c_str());
  const int link_errno = errno;
  fs::remove(own, ec);
  if (linked != 0 && link_errno != EEXIST)
    throw UserError(fmt::format("cannot write '{}': {}", (out / kStudyMarker).string(),
                                std::strerror(link_errno)));
  if (linked != 0) check_marker(out, name);
}

}  // namespace granshock

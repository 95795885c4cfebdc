// A run's text file that is only ever appended to (docs/output_format.md, "The run's log
// and build"): log.txt and thermo.txt. Opened without following a link planted under its
// name (O_NOFOLLOW) and refused when it has a second name (a hard link: appending would
// change that file too); one write per line, so that with O_APPEND no line is split by
// another writer and a process killed between writes leaves whole lines. A write that
// fails (a full disk) is said once on stderr, naming what is lost, and the file is then
// left alone: the run's own files decide whether it can resume.
#pragma once

#include <filesystem>
#include <string>

namespace granshock {

class AppendedFile {
 public:
  // `lost`: what the run goes on without when a write fails ("its log").
  explicit AppendedFile(std::string lost) : lost_(std::move(lost)) {}
  AppendedFile(const AppendedFile&) = delete;
  AppendedFile& operator=(const AppendedFile&) = delete;
  ~AppendedFile();

  // Creates `path` if needed and opens it for appending. Throws UserError when it cannot,
  // or when the file has more than one name (io/marked_directory.hpp, refuse_hard_link).
  void open(const std::filesystem::path& path);
  bool is_open() const { return fd_ >= 0; }
  // Whether the file was empty when opened (a new file: a header goes first).
  bool was_empty() const { return was_empty_; }
  // Appends `text` (whole lines, with their newlines) in one write.
  void append(const std::string& text);

 private:
  std::string lost_;
  std::filesystem::path path_;
  int fd_ = -1;
  bool was_empty_ = false;
  bool failed_ = false;
};

}  // namespace granshock

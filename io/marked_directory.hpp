// What granshock's own directories share (docs/output_format.md, "The run directory"): a
// marker file saying that granshock made the directory, an exclusive lock on the marker
// while one granshock process writes there, and outputs that are only ever files
// granshock creates itself. The run directory (run_directory.hpp) and the directory of
// `granshock fields --out` (fields_directory.hpp) are built on these pieces.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace granshock {

// The markers: a run directory, the directory of `granshock fields DIR --out OUT`, and a
// study directory (cases/study/study_directory.hpp).
inline constexpr const char* kRunMarker = ".granshock-run";
inline constexpr const char* kFieldsMarker = ".granshock-fields";
inline constexpr const char* kStudyMarker = ".granshock-study";

// A marker's `key = value` lines.
struct DirectoryMarker {
  int format = 0;       // the directory layout's version
  long pid = 0;         // the granshock process that claimed the directory last
  std::string version;  // that process's granshock version
  bool empty = false;   // a 0-byte marker (see check_marker_format)
  std::filesystem::path path;
  unsigned long links = 1;  // its hard links: more than 1 is a file with another name
};

// The marker dir/name, if there is one. A marker that is not a regular file is refused,
// so that granshock never follows a link planted in its place.
std::optional<DirectoryMarker> read_marker(const std::filesystem::path& dir, const char* name);

// Throws UserError unless the marker is of `format`; `kind` names the layout in the
// message ("run-directory"). An empty marker counts as `format` (see the .cpp). A marker
// with a second name is refused first (refuse_hard_link): whatever it holds, a claim would
// write it.
void check_marker_format(const std::filesystem::path& dir, const DirectoryMarker& marker,
                         int format, const std::string& kind);

// Whether another open file (another process, or another claim in this one) holds the
// lock on the marker dir/name.
bool locked_by_another(const std::filesystem::path& dir, const char* name);

// Whether another open file holds the lock on the marker dir/name exclusively (a writer);
// readers' shared locks do not count.
bool locked_for_writing(const std::filesystem::path& dir, const char* name);

// Throws the one-line refusal of a directory that another granshock holds.
[[noreturn]] void refuse_in_use(const std::filesystem::path& dir, const DirectoryMarker& marker);

bool directory_is_empty(const std::filesystem::path& dir);

// Whether dir holds nothing but an empty marker `name`: a claim of a new or empty
// directory that ended before it wrote anything.
bool holds_only_an_empty_marker(const std::filesystem::path& dir, const char* name);

// Throws UserError unless the directory can be created: its nearest existing ancestor
// must be a writable directory that takes a new directory (made and removed again).
void check_creatable(const std::filesystem::path& dir);

// Throws UserError, naming the first offender, unless every output (a path relative to
// dir, perhaps in a subdirectory) is absent or a regular file, and every subdirectory on
// the way is absent or a real directory: no symbolic link, no hard-linked file, no
// directory where granshock writes a file, no special file. Run before anything is written or
// removed, so that a refusal changes nothing.
void check_outputs_are_files(const std::filesystem::path& dir,
                             const std::vector<std::string>& outputs);

// Throws the one-line refusal of a file granshock would write that has more than one name
// (a hard link): like a symbolic link, writing it would change a file outside granshock's.
[[noreturn]] void refuse_hard_link(const std::filesystem::path& path, unsigned long links);

// Removes those outputs that exist (check_outputs_are_files first), then the
// subdirectories it removed one from when nothing else is left in them.
void remove_outputs(const std::filesystem::path& dir, const std::vector<std::string>& outputs);

// exclusive: one granshock writes in the directory. shared: granshock reads it (`fields
// RUN --out OUT`), and none may write it meanwhile; several may read it at once.
enum class LockKind { exclusive, shared };

// The lock on a directory's marker, held while one granshock writes there (or others read)
// and released when the object goes (or the process ends, even by kill -9).
class DirectoryLock {
 public:
  // Creates the marker dir/name when there is none (O_EXCL: of two claims at once, one
  // creates it), locks it exclusively (refuse_in_use when another holds it) and writes
  // `header`, the format, this granshock's version and pid into it. `dir` must exist.
  static DirectoryLock take(const std::filesystem::path& dir, const char* name,
                            const std::string& header, int format);

  // Locks the existing marker dir/name without writing it (refuse_in_use when another
  // holds a lock that conflicts): a command holds the directory from its first read, and
  // a refusal found while it reads leaves the marker as it was. stamp() claims it after.
  static DirectoryLock hold(const std::filesystem::path& dir, const char* name, LockKind kind);

  // Writes the marker's lines (take() does it at once): an exclusive lock only.
  void stamp(const std::string& header, int format);

  DirectoryLock() = default;
  DirectoryLock(DirectoryLock&& other) noexcept;
  DirectoryLock& operator=(DirectoryLock&& other) noexcept;
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;
  ~DirectoryLock();

 private:
  explicit DirectoryLock(int fd) : fd_(fd) {}
  int fd_ = -1;
  std::filesystem::path dir_;
  std::string name_;
  bool created_ = false;  // take() made the marker: a failed stamp removes it again
};

}  // namespace granshock

// Writing a file so that readers never see half of it: write to a temporary name in the
// same directory, then rename over the target (atomic on POSIX file systems).
//
// granshock writes only files it creates itself (docs/output_format.md, "The run
// directory"): the temporary is created new (O_EXCL, O_NOFOLLOW), so a symbolic link or
// another file planted under its name is never written through. A stale temporary that
// is a regular file (left by a killed process) is removed first; anything else under that
// name is refused. The rename replaces the target's directory entry, never what a link
// there points to.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace granshock {

// Throws UserError naming the path when the directory is not writable or the write fails
// (then the temporary is removed and the previous file stays).
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

// The same for a file too large to hold in memory: `produce` hands its text piece by piece
// to the writer it is given. An exception of `produce` removes the temporary and goes on.
using AtomicWrite = std::function<void(const std::string& piece)>;
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const AtomicWrite&)>& produce);

// Makes room for a temporary file that granshock is about to create: removes `tmp` when
// it is a regular file, does nothing when it is absent, and throws UserError when it is
// a symbolic link, a directory or a special file.
void remove_stale_temporary(const std::filesystem::path& tmp);

// Creates `dir` when it does not exist (its parent must) and checks that it is a real
// directory, not a symbolic link to one: the directory granshock writes its figures
// into. Throws UserError naming the path otherwise.
void make_real_directory(const std::filesystem::path& dir);

}  // namespace granshock

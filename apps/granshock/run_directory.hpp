// The run directory of `granshock run`: deciding, before anything is written, whether
// it may be created, replaced or resumed, so that a refused run leaves nothing behind.
#pragma once

#include <filesystem>

namespace granshock {

enum class DirectoryMode { create, overwrite, resume };

// Throws UserError when the directory exists without --overwrite/--resume, when
// --resume finds no checkpoint, or when the directory cannot be created or written.
// Does not create anything.
void check_run_directory(const std::filesystem::path& dir, DirectoryMode mode);
// Creates (or, for overwrite, empties) the directory; called once the run is accepted.
void prepare_run_directory(const std::filesystem::path& dir, DirectoryMode mode);

}  // namespace granshock

// checkpoint.h5: everything a run needs to continue bitwise where it stopped (the solver
// state plus the run loop's own counters), written atomically so that an interruption
// while writing leaves the previous checkpoint intact. Layout: docs/output_format.md.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/checkpoint_extras.hpp"
#include "core/solver_state.hpp"

namespace granshock {

// The layout versions of checkpoint.h5 (docs/output_format.md, "Checkpoint format
// versions"): this granshock writes kCheckpointFormat and reads every format from
// kOldestCheckpointFormat on.
// 3: /state/history_wall_spring became history_obstacle_spring.
// 4: /state@skin, /state@last_build_step and /run@cpu_seconds_so_far are always present
//    (format 3 files may lack each of them), and a format-4 file lacking one is refused.
inline constexpr int kCheckpointFormat = 4;
inline constexpr int kOldestCheckpointFormat = 3;

// Writes path + ".tmp", closes and syncs it, then renames it over `path`. Throws
// UserError naming the path when the directory is not writable (no .tmp is left), and
// std::invalid_argument when a per-particle array of `state` does not divide into rows.
void write_checkpoint(const std::filesystem::path& path, const SolverState& state,
                      const CheckpointExtras& extras);

// The --set overrides a checkpoint's run was set up with (CheckpointExtras), or nothing
// when it holds none (a format-3 file may not: CheckpointExtras::scene_overrides), is
// missing or cannot be read (read_checkpoint then says why).
std::optional<std::vector<std::string>> read_checkpoint_overrides(
    const std::filesystem::path& path);

// The most overrides a checkpoint may list (a run's legs each add theirs).
inline constexpr long kMaxSceneOverrides = 100000;

// Reads a checkpoint back exactly. Throws UserError naming the path when it is missing,
// unreadable, damaged (checksum), not a granshock checkpoint, or when its contents do not
// agree with each other (core/checkpoint_checks.hpp: check_state, check_extras).
SolverState read_checkpoint(const std::filesystem::path& path, CheckpointExtras& extras);

}  // namespace granshock

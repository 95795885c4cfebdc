// `granshock run SCENE.toml`: simulates a bow-shock scene and writes its run directory
// (DESIGN.md section 3): run.h5 (+ run.xmf), checkpoint.h5 and summary.json.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace granshock {

// A run that blew up numerically (NaN state, exploding energy): exit code 4.
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;  // empty: runs/<scene name>
  std::vector<std::string> overrides;
  bool overwrite = false;
  bool resume = false;
  bool force = false;         // run past the stable time step
  long stop_after_steps = 0;  // > 0: checkpoint and stop after this many steps (batch jobs)
  bool quiet = false;         // no progress lines
  bool dry_run = false;       // check the scene and the directory, print the resolved scene
};

// What `granshock run --dry-run` checks: the scene, the limits and guards of a run and the
// output directory, without writing anything. Throws UserError where the run would be
// refused; returns the resolved scene (TOML), the directory and the warnings.
struct RunCheck {
  std::string resolved_scene;
  std::filesystem::path directory;
  std::vector<std::string> warnings;
};
RunCheck check_run(const RunOptions& options);

// Returns the process exit code: 0 done (or stopped by --stop-after-steps), 130/143
// interrupted by SIGINT/SIGTERM after writing a checkpoint. Throws UserError for bad input.
int run_scene(const RunOptions& options);

}  // namespace granshock

#include "run_command.hpp"

#include <fmt/format.h>

#include <iostream>

#include "bow_shock_run.hpp"
#include "models/restitution_calibration.hpp"
#include "run_checks.hpp"
#include "run_directory.hpp"
#include "scene_file.hpp"

namespace granshock {

std::filesystem::path run_directory_of(const RunOptions& o, const Scene& scene) {
  return o.out_dir.empty() ? std::filesystem::path("runs") / scene.name : o.out_dir;
}

RunCheck check_run(const RunOptions& o) {
  LoadedScene loaded = load_scene_file(o.scene_file, o.overrides);
  RunCheck c;
  c.warnings = check_scene_before_run(loaded.scene, o.force);
  // The guard again with the damping the run will calibrate (restitution_mode = "discrete").
  if (loaded.scene.setup.contacts.restitution_mode == RestitutionMode::discrete) {
    apply_restitution_mode(loaded.scene.setup);
    c.warnings = check_scene_before_run(loaded.scene, o.force);
  }
  c.directory = run_directory_of(o, loaded.scene);
  RunDirectory::check(c.directory, o.resume      ? DirectoryMode::resume
                                   : o.overwrite ? DirectoryMode::overwrite
                                                 : DirectoryMode::create);
  c.resolved_scene = loaded.resolved;
  const TimeStepAssessment guard = assess_time_step(loaded.scene);
  c.time_step = fmt::format(
      "time.dt = {:.4g} s is {:.3g} t_c ({} at {:.3g} m/s, t_c = {:.4g} s); stable limit {:.4g} s",
      guard.dt, guard.dt_over_tc(), guard.stiffest_pair, guard.impact_speed, guard.t_c,
      guard.dt_stable);
  c.calibrates_inflow = loaded.scene.inflow.mach_at == MachReference::inlet_bins;
  return c;
}

int run_scene(const RunOptions& o) {
  if (o.dry_run) {
    const RunCheck c = check_run(o);
    for (const std::string& w : c.warnings) std::cerr << "granshock: warning: " << w << "\n";
    // A TOML comment, so that the output stays a scene file.
    if (c.calibrates_inflow)
      std::cout << "# inflow.mach_at = \"inlet_bins\": the run calibrates sigma before it "
                   "starts; the sigma below is its first guess\n";
    std::cout << "# " << c.time_step << "\n" << c.resolved_scene;
    return 0;
  }
  BowShockRun run(o, load_scene_file(o.scene_file, o.overrides));
  return run.execute();
}

}  // namespace granshock

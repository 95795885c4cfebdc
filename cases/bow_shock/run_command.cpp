#include "cases/bow_shock/run_command.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <iostream>
#include <optional>

#include "cases/accuracy/accuracy_choice.hpp"
#include "cases/bow_shock/bow_shock_run.hpp"
#include "cases/bow_shock/prepared_scene.hpp"
#include "cases/bow_shock/run_checks.hpp"
#include "core/failure_agreement.hpp"
#include "core/shell_text.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"
#include "io/run_directory.hpp"
#include "io/scene_file.hpp"

namespace granshock {

RunOptions with_run_overrides(const RunOptions& given, bool speaks) {
  if (!given.resume) return given;
  // --resume continues the run as it was set up: the scene file with the --set of every
  // earlier leg, which its checkpoint keeps, then the --set given now (docs/output_format.md,
  // "Resuming"). The file alone names the default directory.
  // With --out the directory is known without the scene: the file with only the --set given
  // now may not be a valid scene (a shorter time.duration than the file's production_start,
  // where an earlier leg's --set moved it).
  const std::filesystem::path dir =
      given.out_dir.empty()
          ? run_directory_of(given, load_scene_file(given.scene_file, given.overrides).scene)
          : given.out_dir;
  const std::optional<std::vector<std::string>> earlier =
      read_checkpoint_overrides(dir / "checkpoint.h5");
  if (!earlier || earlier->empty()) return given;  // the resume's checks say what is missing
  // An earlier --set given again moves to the end with the others: a resume that repeats
  // the run's own --set keeps the list (and the checkpoint) as it was.
  RunOptions o = given;
  o.overrides.clear();
  for (const std::string& set : *earlier)
    if (std::find(given.overrides.begin(), given.overrides.end(), set) == given.overrides.end())
      o.overrides.push_back(set);
  o.overrides.insert(o.overrides.end(), given.overrides.begin(), given.overrides.end());
  const std::size_t kept = o.overrides.size() - given.overrides.size();
  if (speaks && !given.quiet && kept > 0) {
    std::string sets;
    for (std::size_t k = 0; k < kept; ++k) sets += " --set " + shell_quote(o.overrides[k]);
    std::cerr << "granshock: note: --resume keeps the run's own" << sets << "\n";
  }
  return o;
}

RunCheck check_run(const RunOptions& given) {
  const RunOptions o = with_run_overrides(given, false);
  PrepareOptions how;
  how.force = o.force;
  how.certified = certified_step(o.accuracy_choice);
  how.calibrate_inflow = false;  // the channel runs are the run's (the report says so)
  const PreparedScene prepared = prepare_scene(load_scene_file(o.scene_file, o.overrides), how);
  RunCheck c;
  c.warnings = prepared.warnings;
  c.directory = run_directory_of(o, prepared.scene());
  RunDirectory::check(c.directory, o.resume      ? DirectoryMode::resume
                                   : o.overwrite ? DirectoryMode::overwrite
                                                 : DirectoryMode::create);
  c.resolved_scene = prepared.loaded.resolved;
  const TimeStepAssessment guard = assess_time_step(prepared.scene());
  c.time_step = fmt::format(
      "time.dt = {:.4g} s is {:.3g} t_c ({} at {:.3g} m/s, t_c = {:.4g} s); stable limit {:.4g} s",
      guard.dt, guard.dt_over_tc(), guard.stiffest_pair, guard.impact_speed, guard.t_c,
      guard.dt_stable);
  c.calibrates_inflow = prepared.scene().inflow.mach_at == MachReference::inlet_bins;
  return c;
}

namespace {

// --accuracy: the chosen settings become --set overrides after the user's own, so that the
// resolved scene (run.h5, resume) records them; the choice is said before anything runs.
RunOptions with_accuracy_choice(const RunOptions& given, bool speaks) {
  if (given.accuracy.empty()) return given;
  RunOptions o = given;
  const AccuracyChoice choice =
      choose_accuracy(o.scene_file, o.overrides, o.accuracy, o.accuracy_table);
  o.overrides.insert(o.overrides.end(), choice.overrides.begin(), choice.overrides.end());
  o.accuracy_choice = choice.record;
  // On --dry-run stdout is a scene file: the report goes there as TOML comments.
  for (const std::string& line : speaks ? choice.report : std::vector<std::string>())
    (o.dry_run ? std::cout : std::cerr)
        << (o.dry_run ? "# accuracy: " : "granshock: accuracy: ") << line << "\n";
  return o;
}

}  // namespace

int run_scene(const RunOptions& given, const Communicator& comm) {
  RunOptions o;
  agree_on_failure(comm, [&] {
    if (given.overwrite && given.resume)
      throw UserError("--overwrite and --resume exclude each other");
    o = with_accuracy_choice(given, comm.is_root());
  });
  if (o.dry_run) {
    if (!comm.is_root()) return 0;
    const RunCheck c = check_run(o);
    for (const std::string& w : c.warnings) std::cerr << "granshock: warning: " << w << "\n";
    // A TOML comment, so that the output stays a scene file.
    if (c.calibrates_inflow)
      std::cout << "# inflow.mach_at = \"inlet_bins\": the run calibrates sigma before it "
                   "starts; the sigma below is its first guess\n";
    std::cout << "# " << c.time_step << "\n" << c.resolved_scene;
    return 0;
  }
  std::optional<LoadedScene> loaded;
  agree_on_failure(comm, [&] {
    o = with_run_overrides(o, comm.is_root());
    loaded = load_scene_file(o.scene_file, o.overrides);
  });
  BowShockRun run(o, std::move(*loaded), comm);
  return run.execute();
}

}  // namespace granshock

#include "cases/bow_shock/run_resume.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>

#include "analysis/json_file.hpp"
#include "cases/bow_shock/run_state.hpp"
#include "cases/bow_shock/sampling_plan.hpp"
#include "core/checkpoint_checks.hpp"
#include "core/user_error.hpp"
#include "io/checkpoint_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

ResumePoint read_resume_point(const fs::path& dir, const LoadedScene& scene,
                              const InflowController& inflow) {
  const fs::path path = dir / "checkpoint.h5";
  ResumePoint point;
  point.state = read_checkpoint(path, point.extras);
  // The same values written in other digits (a checkpoint of a granshock that wrote every
  // number with 17: io/shortest_floats.hpp) are the same scene.
  // A format-3 checkpoint may hold another law's keys (io/scene_file.hpp).
  const std::string stored = without_other_laws_keys(point.extras.scene_resolved);
  const std::vector<std::string> keys = stored == scene.resolved
                                            ? std::vector<std::string>()
                                            : differing_keys(stored, scene.resolved);
  const std::vector<std::string> fixed = keys_fixed_on_resume(keys);
  if (!fixed.empty()) {
    throw UserError(fmt::format(
        "--resume: scene key{} {} differ{} from the run in '{}'; resume with the same scene "
        "file and --set options (docs/scene_format.md, \"Resuming\": only time.duration and "
        "time.production_start may change)",
        fixed.size() == 1 ? "" : "s", fmt::join(fixed, ", "), fixed.size() == 1 ? "s" : "",
        dir.string()));
  }
  // The checkpoint is checked against its own scene's schedule, then the change of its
  // time keys against what it holds (run_extension.hpp).
  const Scene before = keys.empty()
                           ? scene.scene
                           : parse_scene(stored, {}, path.string() + ":/scene/resolved").scene;
  try {
    check_run(point.state, point.extras,
              run_fit(before, inflow, SamplingPlan(before), point.state.step));
  } catch (const InvalidCheckpoint& e) {
    throw refuse_checkpoint(path, e);
  }
  point.extension = plan_extension(before, scene.scene, point.state.step);
  return point;
}

void resume_from(ResumePoint& point, const fs::path& dir, Solver& solver, InflowController& inflow,
                 std::vector<long>& samples) {
  try {
    solver.import_state(point.state);
  } catch (const InvalidCheckpoint& e) {
    throw refuse_checkpoint(dir / "checkpoint.h5", e);
  }
  restore_run_state(point.extras, solver, inflow, samples);
  // A new production window (run_extension.hpp): the earlier one's sums go, and the
  // checkpoint's step is sampled where the new window samples it and the earlier did not.
  const RunExtension& e = point.extension;
  if (e.samples_dropped > 0) {
    solver.restore_field_sums(std::vector<double>(solver.field_sums(false).size(), 0.0),
                              std::vector<double>(solver.field_sums(true).size(), 0.0));
    samples.assign(samples.size(), 0);
  }
  if (e.catch_up_block >= 0) {
    solver.sample_fields(e.catch_up_block);
    ++samples[std::size_t(e.catch_up_block)];
  }
  point.state = SolverState{};  // the solver holds it now
}

EarlierSummary read_earlier_summary(const fs::path& dir) {
  EarlierSummary earlier;
  const fs::path path = dir / "summary.json";
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(path, ec))) return earlier;
  try {
    const JsonFile file = read_json_file(path, "summary");
    if (!file.value.is_object()) return earlier;
    const nlohmann::json warnings = file.value.value("warnings", nlohmann::json());
    if (warnings.is_array() && std::all_of(warnings.begin(), warnings.end(),
                                           [](const nlohmann::json& w) { return w.is_string(); }))
      earlier.warnings = warnings;
    earlier.rate = file.value.value("particle_steps_per_second", nlohmann::json());
  } catch (const UserError&) {
  }
  return earlier;
}

}  // namespace granshock

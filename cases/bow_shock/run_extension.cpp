#include "cases/bow_shock/run_extension.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "cases/bow_shock/sampling_plan.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace {

constexpr const char* kDuration = "time.duration";
constexpr const char* kProductionStart = "time.production_start";

// /scene/extensions: one row per extension (docs/output_format.md).
constexpr const char* kExtensions = "/scene/extensions";
constexpr const char* kColumns =
    "step, time, duration_before, duration_after, production_start_before, "
    "production_start_after, samples_dropped";
constexpr long kColumnCount = 7;

long total(const std::vector<long>& samples) {
  return std::accumulate(samples.begin(), samples.end(), 0L);
}

}  // namespace

std::vector<std::string> keys_fixed_on_resume(const std::vector<std::string>& differing) {
  std::vector<std::string> fixed;
  for (const std::string& key : differing)
    if (key != kDuration && key != kProductionStart) fixed.push_back(key);
  return fixed;
}

RunExtension plan_extension(const Scene& before, const Scene& after, long step) {
  RunExtension e;
  e.step = step;
  e.time = double(step) * after.setup.dt;
  e.duration_before = before.run.duration_s;
  e.duration_after = after.run.duration_s;
  e.production_start_before = before.run.production_start_s;
  e.production_start_after = after.run.production_start_s;
  if (!e.changes()) return e;
  if (e.duration_after != e.duration_before && after.total_steps() <= step)
    throw UserError(fmt::format(
        "--resume: scene key '{}' = {} s (was {} s) ends by the checkpoint at t = {} s "
        "(step {}): a resume may lengthen the run, not end it before what it has simulated",
        kDuration, e.duration_after, e.duration_before, e.time, step));

  // The samples a checkpoint holds are those its own window took by its step (checked by
  // check_run); the new window must hold exactly the same, in the same blocks, or none.
  const SamplingPlan old_plan(before), new_plan(after);
  std::vector<long> held = old_plan.samples_by(step);
  const long taken = total(held);
  bool taken_at_step = old_plan.due(step);
  if (new_plan.first_step() >= step && taken > 0) {
    e.samples_dropped = taken;
    held.assign(held.size(), 0);
    taken_at_step = false;
  }
  if (new_plan.due(step) && !taken_at_step) {
    e.catch_up_block = new_plan.block_of(step);
    ++held[std::size_t(e.catch_up_block)];
  }
  if (held == new_plan.samples_by(step)) return e;

  if (e.production_start_after != e.production_start_before)
    throw UserError(fmt::format(
        "--resume: scene key '{}' = {} s (was {} s): the checkpoint at t = {} s holds the "
        "{} field samples of a window from {} s, not the {} a window from {} s takes by "
        "then; keep {} s, or move it to t = {} s or later to start a new window (the "
        "earlier samples are then dropped)",
        kProductionStart, e.production_start_after, e.production_start_before, e.time, taken,
        e.production_start_before, total(new_plan.samples_by(step)), e.production_start_after,
        e.production_start_before, e.time));
  throw UserError(fmt::format(
      "--resume: scene key '{}' = {} s (was {} s): the {} field samples taken by the "
      "checkpoint at t = {} s lie in the output.blocks = {} blocks of the window {} to {} "
      "s, and a window to {} s cuts its blocks elsewhere, so the block sums cannot continue; "
      "set time.production_start to {} s or later to start a new window (the earlier samples "
      "are then dropped), or start again with --overwrite",
      kDuration, e.duration_after, e.duration_before, taken, e.time, old_plan.blocks(),
      e.production_start_before, e.duration_before, e.duration_after, e.time));
}

std::string extension_note(const RunExtension& e) {
  std::string note = fmt::format("granshock: --resume at step {} (t = {} s):", e.step, e.time);
  if (e.duration_after != e.duration_before)
    note += fmt::format(" time.duration {} s -> {} s", e.duration_before, e.duration_after);
  if (e.production_start_after != e.production_start_before)
    note += fmt::format("{} time.production_start {} s -> {} s",
                        e.duration_after != e.duration_before ? "," : "", e.production_start_before,
                        e.production_start_after);
  if (e.samples_dropped > 0)
    note += fmt::format(
        "; a new production window: the {} field samples of the earlier one are "
        "dropped",
        e.samples_dropped);
  return note + " (run.h5: /scene/extensions)";
}

nlohmann::json record_extension(RunFile& file, const std::string& scene_as_given,
                                const std::string& scene_resolved, const RunExtension& e) {
  if (file.scene_resolved() != scene_resolved) file.replace_scene(scene_as_given, scene_resolved);
  std::vector<double> rows;
  const bool had = file.has(kExtensions);
  if (had) {
    std::vector<long> shape;
    rows = file.read_array(kExtensions, &shape);
    if (shape.size() != 2 || shape[1] != kColumnCount) rows.clear();
  }
  // Rows from after the checkpoint are of a leg this one redoes.
  std::vector<double> kept;
  for (std::size_t r = 0; r + kColumnCount <= rows.size(); r += kColumnCount)
    if (rows[r] < double(e.step))
      kept.insert(kept.end(), rows.begin() + long(r), rows.begin() + long(r + kColumnCount));
  if (e.changes())
    kept.insert(kept.end(),
                {double(e.step), e.time, e.duration_before, e.duration_after,
                 e.production_start_before, e.production_start_after, double(e.samples_dropped)});
  if (had || !kept.empty()) {
    file.write_array(kExtensions, kept, {long(kept.size()) / kColumnCount, kColumnCount});
    file.write_attribute(kExtensions, "columns", std::string(kColumns));
  }
  nlohmann::json listed = nlohmann::json::array();
  for (std::size_t r = 0; r + kColumnCount <= kept.size(); r += kColumnCount)
    listed.push_back({{"step", long(kept[r])},
                      {"time", kept[r + 1]},
                      {"duration_before", kept[r + 2]},
                      {"duration_after", kept[r + 3]},
                      {"production_start_before", kept[r + 4]},
                      {"production_start_after", kept[r + 5]},
                      {"samples_dropped", long(kept[r + 6])}});
  return listed;
}

}  // namespace granshock

#include "cases/study/study_preflight.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/user_error.hpp"
#include "io/run_directory.hpp"
#include "io/scene_file.hpp"

namespace granshock {

namespace {

// The keys in which a stored run's scene differs from the case's. With inflow.mach_at =
// "inlet_bins" the run stores the sigma it calibrated (docs/fields.md), not the first guess
// the plan has, and the resolved scene holds sigma but not the target Mach number: then
// inflow.sigma does not count, and the target and its reference are compared with the
// run's summary.json (ma_inf_target, inflow_mach_at) instead.
std::vector<std::string> scene_differences(const PlannedCase& c, const std::string& stored) {
  std::vector<std::string> keys = differing_keys(stored, c.resolved);
  if (c.scene.inflow.mach_at != MachReference::inlet_bins) return keys;
  keys.erase(std::remove(keys.begin(), keys.end(), "inflow.sigma"), keys.end());
  const nlohmann::json summary = read_summary(c.dir);
  if (!summary.is_object()) return keys;
  const nlohmann::json at = summary_value(summary, "inflow_mach_at");
  if (!at.is_string() || at.get<std::string>() != to_string(c.scene.inflow.mach_at))
    keys.push_back("inflow.mach_at");
  const nlohmann::json target = summary_value(summary, "ma_inf_target");
  if (!target.is_number() || !c.scene.inflow.target_mach ||
      target.get<double>() != *c.scene.inflow.target_mach)
    keys.push_back("inflow.mach");
  return keys;
}

void check_stored_scene(const StudyPlan& plan, const PlannedCase& c) {
  const std::string stored = stored_scene(c.dir);
  if (stored.empty()) return;  // unreadable now (a run holds it): the run itself checks
  const std::vector<std::string> keys = scene_differences(c, stored);
  if (keys.empty()) return;
  throw UserError(fmt::format(
      "study file '{}': case '{}' (--case {}): '{}' holds a run of another scene (scene key{} "
      "{} differ{}); move it away, or choose another --out",
      plan.spec.file.string(), c.spec.name, c.spec.index, c.dir.string(),
      keys.size() == 1 ? "" : "s", fmt::join(keys, ", "), keys.size() == 1 ? "s" : ""));
}

}  // namespace

CaseAction action_for(CaseState state) {
  CaseAction a;
  a.state = state;
  a.resume = state == CaseState::resumable;
  a.overwrite = state == CaseState::restartable;
  return a;
}

void check_case_directories(const StudyPlan& plan, const std::vector<std::size_t>& selected) {
  for (std::size_t k : selected) {
    const PlannedCase& c = plan.cases[k];
    const CaseAction a = action_for(inspect_planned_case(plan, c).state);
    if (a.state != CaseState::missing) check_stored_scene(plan, c);
    if (a.state == CaseState::finished || a.state == CaseState::needs_fields) continue;
    try {
      RunDirectory::check(c.dir, a.resume      ? DirectoryMode::resume
                                 : a.overwrite ? DirectoryMode::overwrite
                                               : DirectoryMode::create);
    } catch (const UserError& e) {
      throw UserError(fmt::format("study file '{}': case '{}' (--case {}): {}",
                                  plan.spec.file.string(), c.spec.name, c.spec.index, e.what()));
    }
  }
}

}  // namespace granshock

// `granshock run --accuracy BUDGET`: the cheapest measured settings (time step, stiffness
// softening, precision) whose known error is within the budget (docs/accuracy.md,
// "Choosing settings for an error budget").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cases/accuracy/accuracy_table.hpp"
#include "cases/accuracy/certified_step.hpp"

namespace granshock {

// "2%" -> 0.02. Throws UserError for anything but a positive percentage.
double parse_error_budget(const std::string& text);

// What the budget allows, in the table's terms.
struct SettingChoice {
  MeasuredSetting setting;  // a copy of the case: it changes at most dt and softening
  bool single_precision = false;
  bool certified = true;  // false: nothing met the budget; the most accurate case is used
  // Its measured speed per particle-step against the table's case at softening 1 in double
  // nearest in dt/t_c (softening costs per step), times single's measured gain where
  // single is chosen: with the ratio of the steps, the speed against the scene as given.
  double step_speed = 1;
  std::string step_speed_by;         // how step_speed was measured; empty where it is 1
  std::vector<std::string> reasons;  // one line each: what was chosen and what was not, why
};

// Among the cases that change only dt and softening, the fastest whose error bound is
// within the budget; none: the reference. Single precision is added where its own case is
// within the budget and was measured faster than the scene in double.
SettingChoice choose_setting(const AccuracyTable& table, double budget);

// The choice applied to a scene: dt = (dt/t_c of the case) x t_c of this scene at the chosen
// softening (the time-step guard's t_c), the sample interval kept in simulated time; where
// nothing is certified (outside the table's range, a budget below its noise floor), no
// override: the scene as given, and the report says why. Its
// speed is stated against the scene as given (its own dt, softening and precision): the
// ratio of the steps times step_speed; the table's speed-up over its reference beside it.
// The record's "case" where nothing was certified and the scene runs as given.
inline constexpr const char* kAsGivenCase = "scene as given";

struct AccuracyChoice {
  std::vector<std::string> overrides;  // to append to the run's --set overrides
  std::vector<std::string> report;     // what was chosen and why, one line each
  nlohmann::json record;               // summary.json: accuracy_choice
};
AccuracyChoice choose_accuracy(const std::filesystem::path& scene_file,
                               const std::vector<std::string>& overrides,
                               const std::string& budget_text,
                               const std::filesystem::path& table_file);

// The step a certified choice set (its record, summary.json: accuracy_choice), for the run
// checks: the time-step guard's t_c/10 warning then names the measurement instead of
// contradicting it (docs/accuracy.md). None for no choice or an uncertified one.
std::optional<CertifiedStep> certified_step(const nlohmann::json& accuracy_choice);

// The table used when none is named: the paper case's, measured on this code
// (docs/results/certificate/d50_u2375/trade.json; installed in share/granshock).
std::filesystem::path default_accuracy_table();

}  // namespace granshock

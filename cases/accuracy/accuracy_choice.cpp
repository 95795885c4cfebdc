#include "cases/accuracy/accuracy_choice.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "accuracy_paths.hpp"
#include "analysis/figures.hpp"
#include "cases/accuracy/dt_overrides.hpp"
#include "core/choice_names.hpp"
#include "core/quoted_input.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "kernels/models/time_step_guard.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

bool changes_only(const MeasuredSetting& s, const std::set<std::string>& keys) {
  return std::all_of(s.changed.begin(), s.changed.end(),
                     [&](const std::string& k) { return keys.count(k) > 0; });
}

const MeasuredSetting* find_case(const AccuracyTable& table, const std::string& name) {
  for (const MeasuredSetting& s : table.settings)
    if (s.name == name) return &s;
  return nullptr;
}

std::string percent(double fraction) {
  return std::isfinite(fraction) ? fmt::format("{:.3g} %", 100 * fraction) : "unbounded";
}

std::string describe(const MeasuredSetting& s) {
  return fmt::format(
      "\"{}\" (dt = {:.4g} t_c, softening {:g}{}; error at most {}, set by {}; e_eff {} "
      "off averaged over the phase of the first contact step, {} at one phase; measured at "
      "{:.3g}x the speed of the table's reference)",
      s.name, s.dt_over_tc, s.softening, s.discrete_restitution ? ", discrete restitution" : "",
      percent(s.error_bound), s.bound_by, percent(s.e_eff_error_phase_averaged),
      percent(s.e_eff_error), s.speedup);
}

// Softening lengthens the step but costs per step (more neighbour-list builds): the case's
// measured rate against the table's case at softening 1 in double nearest in dt/t_c. At
// softening 1 the steps alone (the rates of such cases differ by the machine's load).
void measure_step_speed(const AccuracyTable& table, SettingChoice& c) {
  const MeasuredSetting& s = c.setting;
  if (s.softening == 1) return;
  // Nearest in dt/t_c; within 1 % the first in the table (the scene before the cases that
  // change only what the table ignores, such as sample-x4).
  const MeasuredSetting* base = nullptr;
  const auto distance = [&](const MeasuredSetting& b) {
    return std::abs(std::log(b.dt_over_tc / s.dt_over_tc));
  };
  for (const MeasuredSetting& b : table.settings)
    if (b.softening == 1 && !b.single_precision && changes_only(b, {"time.dt"}) &&
        b.particle_steps_per_second > 0 &&
        (base == nullptr || distance(b) < distance(*base) - 0.01))
      base = &b;
  if (base == nullptr || s.particle_steps_per_second <= 0) {
    c.step_speed_by = "the table has no rate to compare: the steps alone";
    return;
  }
  c.step_speed = s.particle_steps_per_second / base->particle_steps_per_second;
  c.step_speed_by = fmt::format(
      "at {:.3g} of the speed per particle-step of softening 1 (the table's \"{}\" against "
      "\"{}\")",
      c.step_speed, s.name, base->name);
}

void choose_precision(const AccuracyTable& table, double budget, SettingChoice& c) {
  const MeasuredSetting* single = nullptr;
  for (const MeasuredSetting& s : table.settings)
    if (s.single_precision && changes_only(s, {"numerics.precision"})) single = &s;
  const MeasuredSetting* scene = find_case(table, "scene");
  if (single == nullptr || scene == nullptr) {
    c.reasons.push_back("double precision: the table has no single-precision case");
    return;
  }
  const double ratio = single->speedup / scene->speedup;
  if (single->error_bound > budget) {
    c.reasons.push_back(fmt::format("double precision: single's error is up to {} ({})",
                                    percent(single->error_bound), single->bound_by));
  } else if (ratio <= 1) {
    c.reasons.push_back(fmt::format(
        "double precision: single was measured at {:.3g}x the speed of double, no faster", ratio));
  } else {
    c.single_precision = true;
    c.step_speed *= ratio;
    c.step_speed_by += (c.step_speed_by.empty() ? "" : ", ") +
                       fmt::format("single precision at {:.3g}x the speed of double", ratio);
    c.reasons.push_back(
        fmt::format("single precision: error at most {} ({}), {:.3g}x the speed of double",
                    percent(single->error_bound), single->bound_by, ratio));
  }
}

// A scene outside where the table was shown to hold: nothing is certified, and the run
// takes the table's most accurate case, as when nothing meets the budget.
SettingChoice reference_outside_range(const AccuracyTable& table, const SceneCorner& corner) {
  SettingChoice c;
  c.certified = false;
  c.setting = *find_case(table, "reference");  // read_accuracy_table requires it
  c.reasons.push_back(fmt::format(
      "not certified for this scene (D/d = {:.3g}, Ma = {:.3g}): {}; its most accurate case "
      "is {}",
      corner.obstacle_over_particle, corner.mach,
      table.range ? "the table's settings were shown to hold for " + describe(*table.range)
                  : std::string("the table states no range where its settings hold (a table "
                                "from before it was recorded: run granshock tradeoff again)"),
      describe(c.setting)));
  return c;
}

// Nothing certified (outside the table's range, or a budget below its noise floor): the
// scene runs as given, and the report says why in its first line after the budget
// (docs/accuracy.md, "Where a certificate holds"). The table's most accurate case would
// cost several times the scene's own settings and certify nothing either.
AccuracyChoice as_given(const LoadedScene& given, const TimeStepAssessment& guard,
                        const SceneCorner& corner, const AccuracyTable& table,
                        const fs::path& table_path, double budget, const SettingChoice& sc) {
  const Scene& s = given.scene;
  AccuracyChoice out;
  out.report.push_back(fmt::format("budget {} on e_eff, delta/D, phi_peak and Ma_inf, from {}",
                                   percent(budget), table_path.string()));
  out.report.push_back("cannot certify: " + sc.reasons.front());
  out.report.push_back(fmt::format(
      "so: nothing changed, the scene as given (dt = {:.4g} s = {:.3g} t_c, softening {:g}, {} "
      "precision, {} restitution)",
      s.setup.dt, guard.dt_over_tc(), s.setup.contacts.softening, choice_name(s.setup.precision),
      choice_name(s.setup.contacts.restitution_mode)));
  out.record = {{"budget", budget},
                {"table", table_path.string()},
                {"case", kAsGivenCase},
                {"certified", false},
                {"why_not", sc.reasons.front()},
                {"error_bound", nullptr},
                {"bound_by", nullptr},
                {"noise_floor", table.noise_floor},
                {"noise_seeds", table.noise_seeds},
                {"speedup_over_scene", 1.0},
                {"scene_dt", s.setup.dt},
                {"dt", s.setup.dt},
                {"dt_over_tc", guard.dt_over_tc()},
                {"softening", s.setup.contacts.softening},
                {"restitution_mode", choice_name(s.setup.contacts.restitution_mode)},
                {"precision", choice_name(s.setup.precision)},
                {"scene_D_over_d", corner.obstacle_over_particle},
                {"scene_mach", corner.mach},
                {"certified_range", table.range ? to_json(*table.range) : nlohmann::json()},
                {"overrides", nlohmann::json::array()}};
  return out;
}

}  // namespace

double parse_error_budget(const std::string& text) {
  const auto bad = [&] {
    return UserError(
        fmt::format("--accuracy {}: give the error budget as a percentage, e.g. --accuracy 2%",
                    quoted_input(text)));
  };
  if (text.size() < 2 || text.back() != '%') throw bad();
  // Decimal digits with at most one point, nothing else: strtod alone would also read hex
  // ("0x5"), "inf", exponents and leading blanks.
  const std::string number = text.substr(0, text.size() - 1);
  const bool decimal = number.find_first_not_of("0123456789.") == std::string::npos &&
                       std::count(number.begin(), number.end(), '.') <= 1 &&
                       number.find_first_of("0123456789") != std::string::npos &&
                       number.size() <= 32;
  if (!decimal) throw bad();
  const double value = std::strtod(number.c_str(), nullptr);
  if (!std::isfinite(value) || value <= 0) throw bad();
  return value / 100;
}

SettingChoice choose_setting(const AccuracyTable& table, double budget) {
  SettingChoice c;
  std::vector<const MeasuredSetting*> candidates;
  for (const MeasuredSetting& s : table.settings)
    if (!s.single_precision &&
        changes_only(s, {"time.dt", "contact.softening", "contact.restitution_mode"}))
      candidates.push_back(&s);
  const MeasuredSetting* best = nullptr;
  for (const MeasuredSetting* s : candidates)
    if (s->error_bound <= budget && (best == nullptr || s->speedup > best->speedup)) best = s;
  if (best == nullptr) {
    c.certified = false;
    c.setting = *find_case(table, "reference");  // read_accuracy_table requires it
    c.reasons.push_back(fmt::format(
        "no measured setting is within {}: the table cannot bound an error below its noise "
        "floor, {} ({}; noise from {} seeds); its most accurate case is {}",
        percent(budget), percent(table.noise_floor), table.noise_floor_by, table.noise_seeds,
        describe(c.setting)));
    return c;  // single precision is a cheaper setting: not without a certified budget
  }
  c.setting = *best;
  c.reasons.push_back(
      fmt::format("chose {}; noise from {} seeds", describe(c.setting), table.noise_seeds));
  for (const MeasuredSetting* s : candidates)
    if (s->speedup > best->speedup)
      c.reasons.push_back("not " + describe(*s) + ": past the budget");
  measure_step_speed(table, c);
  choose_precision(table, budget, c);
  return c;
}

std::optional<CertifiedStep> certified_step(const nlohmann::json& r) {
  if (!r.is_object() || !r.value("certified", false)) return std::nullopt;
  CertifiedStep c;
  c.dt = r.at("dt").get<double>();
  c.why = fmt::format(
      "--accuracy {} chose it and certified it: the trade table's case \"{}\" measured an "
      "error of at most {} (set by {}) at dt = {:.4g} t_c",
      percent(r.at("budget").get<double>()), r.at("case").get<std::string>(),
      percent(r.at("error_bound").get<double>()), r.at("bound_by").get<std::string>(),
      r.at("case_dt_over_tc").get<double>());
  return c;
}

fs::path default_accuracy_table() {
  std::vector<fs::path> candidates;
  if (const fs::path dir = program_directory(); !dir.empty())
    candidates.push_back(dir / ".." / GRANSHOCK_ACCURACY_TABLE_INSTALLED);
  candidates.push_back(GRANSHOCK_ACCURACY_TABLE_SOURCE);
  std::error_code ec;
  for (const fs::path& p : candidates)
    if (fs::is_regular_file(p, ec)) return p;
  std::vector<std::string> tried;
  for (const fs::path& p : candidates) tried.push_back(p.string());
  throw UserError(
      fmt::format("--accuracy: cannot find the measured table (looked at {}); name one with "
                  "--accuracy-table",
                  fmt::join(tried, ", ")));
}

AccuracyChoice choose_accuracy(const fs::path& scene_file,
                               const std::vector<std::string>& overrides,
                               const std::string& budget_text, const fs::path& table_file) {
  const double budget = parse_error_budget(budget_text);
  const fs::path table_path = table_file.empty() ? default_accuracy_table() : table_file;
  const AccuracyTable table = read_accuracy_table(table_path);
  // What the user would run without --accuracy: the speed is claimed against it.
  const LoadedScene given = load_scene_file(scene_file, overrides);
  const TimeStepAssessment given_guard =
      assess_time_step(given.scene.setup, given.scene.fastest_impact_speed());
  const SceneCorner corner = scene_corner(given.scene);
  const SettingChoice sc = table.range && holds_at(*table.range, corner)
                               ? choose_setting(table, budget)
                               : reference_outside_range(table, corner);
  if (!sc.certified) return as_given(given, given_guard, corner, table, table_path, budget, sc);
  const MeasuredSetting& s = sc.setting;
  const MeasuredSetting& reference = *find_case(table, "reference");

  AccuracyChoice out;
  std::vector<std::string> chosen;
  if (s.softening != 1) chosen.push_back(fmt::format("contact.softening={:g}", s.softening));
  if (s.discrete_restitution)
    chosen.push_back(
        fmt::format("contact.restitution_mode=\"{}\"", choice_name(RestitutionMode::discrete)));
  if (sc.single_precision)
    chosen.push_back(
        fmt::format("numerics.precision=\"{}\"", choice_name(Precision::single_precision)));
  std::vector<std::string> all = overrides;
  all.insert(all.end(), chosen.begin(), chosen.end());
  // t_c of this scene at the chosen softening: the case's dt/t_c carries over.
  const LoadedScene loaded = load_scene_file(scene_file, all);
  const TimeStepAssessment guard =
      assess_time_step(loaded.scene.setup, loaded.scene.fastest_impact_speed());
  double dt = s.dt_over_tc * guard.t_c;
  out.report.push_back(fmt::format("budget {} on e_eff, delta/D, phi_peak and Ma_inf, from {}",
                                   percent(budget), table_path.string()));
  out.report.insert(out.report.end(), sc.reasons.begin(), sc.reasons.end());
  if (dt > 0.95 * guard.dt_stable) {
    dt = 0.95 * guard.dt_stable;
    out.report.push_back(fmt::format(
        "dt lowered to 0.95 of this scene's stable limit, {:.4g} s: {:.3g} t_c is past it here",
        guard.dt_stable, s.dt_over_tc));
  }
  // As the override writes it (9 digits), so that the record names the dt the run uses.
  dt = std::stod(fmt::format("{:.9g}", dt));
  const std::vector<std::string> at_dt = overrides_at_dt(loaded.scene, dt);
  chosen.insert(chosen.end(), at_dt.begin(), at_dt.end());
  out.report.push_back(fmt::format("so: {} (t_c = {:.4g} s, {} at {:.3g} m/s)",
                                   fmt::join(chosen, ", "), guard.t_c, guard.stiffest_pair,
                                   guard.impact_speed));
  // Wall time ~ steps / speed per step: the steps' ratio, and what the table measured of
  // the speed per step of the chosen softening and precision (docs/accuracy.md).
  const double steps_ratio = dt / given.scene.setup.dt;
  const double over_scene = steps_ratio * sc.step_speed;
  out.report.push_back(fmt::format(
      "speed: about {:.3g}x that of this scene as given (the chosen dt is {:.3g} times its "
      "own {:.4g} s = {:.4g} t_c{}); the table measured {:.3g}x the speed of its own "
      "reference (dt = {:.4g} t_c)",
      over_scene, steps_ratio, given.scene.setup.dt, given_guard.dt_over_tc(),
      sc.step_speed_by.empty() ? "" : ", " + sc.step_speed_by, s.speedup, reference.dt_over_tc));
  out.overrides = chosen;
  out.record = {
      {"budget", budget},
      {"table", table_path.string()},
      {"case", s.name},
      {"certified", sc.certified},
      {"error_bound", s.error_bound},
      {"bound_by", s.bound_by},
      {"noise_floor", table.noise_floor},
      {"noise_seeds", table.noise_seeds},
      {"e_eff_error_phase_averaged", s.e_eff_error_phase_averaged},
      {"e_eff_error_one_phase", s.e_eff_error},
      {"speedup_over_scene", over_scene},
      {"scene_dt", given.scene.setup.dt},
      {"speedup_over_reference", s.speedup},
      {"reference_dt_over_tc", reference.dt_over_tc},
      {"dt", dt},
      {"dt_over_tc", dt / guard.t_c},
      {"case_dt_over_tc", s.dt_over_tc},
      {"softening", s.softening},
      {"restitution_mode", choice_name(s.discrete_restitution ? RestitutionMode::discrete
                                                              : RestitutionMode::continuous)},
      {"precision", choice_name(sc.single_precision ? Precision::single_precision
                                                    : Precision::double_precision)},
      {"scene_D_over_d", corner.obstacle_over_particle},
      {"scene_mach", corner.mach},
      {"certified_range", table.range ? to_json(*table.range) : nlohmann::json()},
      {"overrides", chosen}};
  return out;
}

}  // namespace granshock

#include "cases/study/study_plan.hpp"

#include <fmt/format.h>

#include <map>

#include "cases/accuracy/accuracy_choice.hpp"
#include "cases/bow_shock/run_checks.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"

namespace granshock {

namespace {

// The scene's TOML without its name: two cases that give the same text run the same scene.
std::string unnamed(Scene scene) {
  scene.name.clear();
  return scene_to_toml(scene);
}

std::vector<std::string> with_common(const StudySpec& s, const std::vector<std::string>& own) {
  std::vector<std::string> all = s.common;
  all.insert(all.end(), own.begin(), own.end());
  return all;
}

LoadedScene load_case(const StudySpec& s, const StudyCase& c) {
  try {
    return load_scene_file(s.base, with_common(s, c.overrides));
  } catch (const UserError& e) {
    throw UserError(fmt::format("study file '{}': case '{}' (--case {}): {}", s.file.string(),
                                c.name, c.index, e.what()));
  }
}

}  // namespace

CaseDirectory inspect_planned_case(const StudyPlan& plan, const PlannedCase& c) {
  return inspect_case_directory(c.dir, c.record_dir, run_overrides(plan.spec, c));
}

std::filesystem::path records_root(const StudySpec& spec, const std::filesystem::path& out) {
  return spec.records.empty() ? out / "records" : spec.records;
}

std::vector<std::string> run_overrides(const StudySpec& s, const PlannedCase& c) {
  // Quoted: a name such as "10" or "true" must stay a string (docs/scene_format.md).
  std::vector<std::string> o{"scene.name=\"" + c.spec.name + "\""};
  for (const std::string& v : with_common(s, c.spec.overrides)) o.push_back(v);
  return o;
}

StudyPlan plan_study(const StudySpec& s, const std::filesystem::path& out) {
  LoadedScene base;
  try {
    base = load_scene_file(s.base, s.common);
  } catch (const UserError& e) {
    throw UserError(fmt::format("study file '{}': base scene{}: {}", s.file.string(),
                                s.common.empty() ? "" : " with [study] set", e.what()));
  }
  const std::string base_text = unnamed(base.scene);

  std::vector<StudyCase> cases = expand_cases(s);
  std::vector<LoadedScene> loaded;
  std::vector<bool> same_as_base;
  for (const StudyCase& c : cases) {
    loaded.push_back(load_case(s, c));
    same_as_base.push_back(unnamed(loaded.back().scene) == base_text);
  }
  if (s.mode == StudyMode::sweep) {
    cases = merge_base_cases(s, cases, same_as_base);
    loaded.clear();
    for (const StudyCase& c : cases) loaded.push_back(load_case(s, c));
  }

  // An error budget: each case's choice on its own scene, its overrides after the case's own
  // (as `granshock run --accuracy` appends them), so that the scene, its cost and the run's
  // resolved scene are the chosen ones.
  std::vector<AccuracyChoice> choices(cases.size());
  if (s.accuracy) {
    for (std::size_t k = 0; k < cases.size(); ++k) {
      try {
        choices[k] = choose_accuracy(s.base, with_common(s, cases[k].overrides), s.accuracy->budget,
                                     s.accuracy->table);
      } catch (const UserError& e) {
        throw UserError(fmt::format("study file '{}': case '{}' (--case {}): {}", s.file.string(),
                                    cases[k].name, cases[k].index, e.what()));
      }
      cases[k].overrides.insert(cases[k].overrides.end(), choices[k].overrides.begin(),
                                choices[k].overrides.end());
      loaded[k] = load_case(s, cases[k]);
    }
  }

  StudyPlan plan{s, out, {}};
  std::map<std::string, std::string> scenes;  // unnamed TOML -> the first case with it
  for (std::size_t k = 0; k < cases.size(); ++k) {
    PlannedCase p;
    p.spec = cases[k];
    p.accuracy_choice = choices[k].record;
    p.accuracy_report = choices[k].report;
    p.dir = out / cases[k].name;
    p.record_dir = records_root(s, out) / "cases" / cases[k].name;
    p.scene = loaded[k].scene;
    const auto [it, fresh] = scenes.emplace(unnamed(p.scene), p.spec.name);
    if (!fresh)
      throw UserError(fmt::format(
          "study file '{}': cases '{}' and '{}' resolve to the same scene; a study runs each "
          "scene once",
          s.file.string(), it->second, p.spec.name));
    p.scene.name = p.spec.name;
    p.resolved = scene_to_toml(p.scene);
    try {
      p.warnings = check_scene_before_run(p.scene, false, 1, certified_step(p.accuracy_choice));
    } catch (const UserError& e) {
      throw UserError(fmt::format("study file '{}': case '{}' (--case {}): {}", s.file.string(),
                                  p.spec.name, p.spec.index, e.what()));
    }
    plan.cases.push_back(std::move(p));
  }
  return plan;
}

}  // namespace granshock

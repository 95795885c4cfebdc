#include "cases/study/study_listing.hpp"

#include <fmt/format.h>

#include "cases/accuracy/accuracy_choice.hpp"
#include "cases/study/case_directory.hpp"
#include "cases/study/study_cost.hpp"
#include "cases/study/study_rate.hpp"

namespace granshock {

namespace {

// "accuracy 5 %: the table's case "soft-1000", certified (error at most 4.57 %), dt = ...",
// from the case's record; an uncertified choice claims no bound.
std::string accuracy_line(const nlohmann::json& r) {
  const std::string verdict = r.at("certified").get<bool>()
                                  ? fmt::format("certified (error at most {:.3g} %)",
                                                100 * r.at("error_bound").get<double>())
                                  : "not certified";
  if (r.at("case") == kAsGivenCase)
    return fmt::format("accuracy {:g} %: not certified, the scene as given, dt = {:.4g} t_c",
                       100 * r.at("budget").get<double>(), r.at("dt_over_tc").get<double>());
  return fmt::format(
      "accuracy {:g} %: the table's case \"{}\", {}, dt = {:.4g} t_c, softening {:g}, {}",
      100 * r.at("budget").get<double>(), r.at("case").get<std::string>(), verdict,
      r.at("dt_over_tc").get<double>(), r.at("softening").get<double>(),
      r.at("precision").get<std::string>());
}

}  // namespace

void print_study_listing(const StudyPlan& plan, const std::vector<std::size_t>& selected,
                         std::ostream& out) {
  const StudyRate rate = study_rate(plan);
  out << fmt::format("study '{}' ({}): {} case{}, mode {}, base scene {}, directory {}\n",
                     plan.spec.name, plan.spec.file.string(), plan.cases.size(),
                     plan.cases.size() == 1 ? "" : "s", to_string(plan.spec.mode),
                     plan.spec.base.string(), plan.out.string());
  if (!plan.spec.common.empty()) out << "every case: " << overrides_text(plan.spec.common) << "\n";
  double total = 0, left = 0;
  std::size_t to_run = 0;
  for (std::size_t k : selected) {
    const PlannedCase& c = plan.cases[k];
    const CaseDirectory dir = inspect_planned_case(plan, c);
    const double cost = expected_particle_steps(c.scene);
    const bool done = dir.state == CaseState::finished || dir.state == CaseState::needs_fields;
    const double rest = done ? 0.0 : expected_particle_steps(c.scene, dir.steps_done);
    total += cost;
    left += rest;
    to_run += done ? 0 : 1;
    out << fmt::format(
        "  --case {:<3} {:<24} {:<10} {:.0f} particles x {} steps = {:.3g} particle-steps, ~{}\n"
        "             {}\n",
        c.spec.index, c.spec.name, to_string(dir.state), expected_particles(c.scene),
        c.scene.total_steps(), cost, duration_text(cost / rate.particle_steps_per_second),
        overrides_text(c.spec.overrides));
    if (!c.accuracy_choice.is_null())
      out << "             " << accuracy_line(c.accuracy_choice) << "\n";
  }
  out << fmt::format(
      "total: {:.3g} particle-steps, ~{} at {:.3g} particle-steps/s ({}); still to run: {} "
      "case{}, {:.3g} particle-steps, ~{}\n",
      total, duration_text(total / rate.particle_steps_per_second), rate.particle_steps_per_second,
      rate.source, to_run, to_run == 1 ? "" : "s", left,
      duration_text(left / rate.particle_steps_per_second));
}

}  // namespace granshock

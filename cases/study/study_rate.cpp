#include "cases/study/study_rate.hpp"

#include <fmt/format.h>

#include <cmath>

#include "cases/study/case_directory.hpp"
#include "cases/study/study_cost.hpp"

namespace granshock {

StudyRate study_rate(const StudyPlan& plan) {
  double particle_steps = 0, seconds = 0;
  int cases = 0;
  for (const PlannedCase& c : plan.cases) {
    const CaseDirectory dir = inspect_planned_case(plan, c);
    // A duration no run reports (zero, negative, not finite) is not a measurement.
    if (dir.state != CaseState::finished || !(dir.wall_seconds > 0) ||
        !std::isfinite(dir.wall_seconds))
      continue;
    particle_steps += expected_particle_steps(c.scene);
    seconds += dir.wall_seconds;
    ++cases;
  }
  if (cases == 0) return {kReferenceRate, "the reference rate for 2 cores, docs/study.md"};
  return {particle_steps / seconds, fmt::format("measured on {} finished case{} of this study",
                                                cases, cases == 1 ? "" : "s")};
}

}  // namespace granshock

// The rate a study's estimates use (docs/study.md, "Cost and ETA"): expected particle-steps
// per wall second, measured on the study's finished cases when it has any, else the
// reference rate of study_cost.hpp.
#pragma once

#include <string>

#include "cases/study/study_plan.hpp"

namespace granshock {

struct StudyRate {
  double particle_steps_per_second = 0;
  std::string source;  // where it comes from, for messages and the Slurm script's comment
};

// Over the finished cases in the study directory: the sum of their expected particle-steps
// over the sum of their wall times (summary.json wall_seconds).
StudyRate study_rate(const StudyPlan& plan);

}  // namespace granshock

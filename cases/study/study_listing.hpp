// `granshock study STUDY.toml --dry-run` (docs/study.md, "Commands"): the cases, each with
// its state, its overrides and its expected cost, and the study's total.
#pragma once

#include <ostream>
#include <vector>

#include "cases/study/study_plan.hpp"

namespace granshock {

void print_study_listing(const StudyPlan& plan, const std::vector<std::size_t>& selected,
                         std::ostream& out);

}  // namespace granshock

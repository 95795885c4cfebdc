// The checks of a study's directories before any case runs (docs/study.md, "Checks before
// anything runs"): the study directory belongs to this study, and each case's run directory
// can be taken as `granshock run` would take it (new, resumed or restarted), and holds a run
// of the case's own scene when it holds one.
#pragma once

#include <vector>

#include "cases/study/case_directory.hpp"
#include "cases/study/study_plan.hpp"

namespace granshock {

// How a case is run from the state of its directory: fresh, --resume, --overwrite (a run
// directory with nothing to resume), or not at all (finished; needs_fields: the field
// analysis only).
struct CaseAction {
  CaseState state = CaseState::missing;
  bool resume = false;
  bool overwrite = false;
};
CaseAction action_for(CaseState state);

// Throws UserError with one line naming the case for a directory that cannot be used, or
// that holds a run of another scene. `selected`: the cases to check (indices into
// plan.cases).
void check_case_directories(const StudyPlan& plan, const std::vector<std::size_t>& selected);

}  // namespace granshock

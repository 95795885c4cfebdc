// Running a study's cases in order, in this process, through `granshock run`'s own code
// (docs/study.md, "Running"): finished cases are skipped, interrupted ones resumed, and a
// progress line before and after each case gives the study's elapsed time and its ETA.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "cases/study/study_plan.hpp"

namespace granshock {

struct StudyRunOptions {
  long stop_after_steps = 0;  // > 0: a case stops after this many steps, and the study with it
  bool quiet = false;         // no progress lines from the runs (the study's own remain)
  bool figures = true;        // each case's figures at its end
};

struct StudyRunResult {
  int exit_code = 0;                    // 130/143 interrupted; 0 otherwise
  bool stopped = false;                 // interrupted, or --stop-after-steps: no table
  std::map<int, std::string> failures;  // case index -> why it failed
};

// Runs plan.cases[k] for each k in `selected`, in that order. A failing case is reported
// and the next one runs; SIGINT or SIGTERM stops the study after the case's checkpoint.
// Writes the record of the finished case `c` (cases/study/case_record.hpp); a failure is a
// warning: the run itself is done.
void record_case(const StudyPlan& plan, const PlannedCase& c);

StudyRunResult run_study_cases(const StudyPlan& plan, const std::vector<std::size_t>& selected,
                               const StudyRunOptions& options);

}  // namespace granshock

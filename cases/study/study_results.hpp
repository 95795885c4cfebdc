// What a study gives once its cases have run, or on `--collect` (docs/study.md, "Outputs"):
// the study table, the field analysis' comparison of the finished cases (the paper's Fig. 6
// and its table, `granshock fields DIR... --out OUT`) and one figure per axis.
#pragma once

#include <map>
#include <string>

#include "cases/study/study_plan.hpp"

namespace granshock {

// Writes the table, the comparison and (with `figures`) the figures into plan.out; a
// missing Python or matplotlib costs only the PNGs (a warning). Lists the cases that are
// not finished. Returns 0 when every case is finished, 1 otherwise (the table has their
// rows).
int write_study_results(const StudyPlan& plan, const std::map<int, std::string>& failures,
                        bool quiet, bool figures);

}  // namespace granshock

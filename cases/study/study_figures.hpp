// The figures of a study (docs/study.md, "Figures"): <out>/figures/<axis>.png for each axis,
// drawn from <out>/study.json by plot_study.py with the interpreter the field figures use
// (analysis/figures.hpp: $GRANSHOCK_PYTHON or /usr/bin/python3, with matplotlib).
#pragma once

#include <filesystem>

#include "cases/study/study_plan.hpp"

namespace granshock {

// The path of plot_study.py: $GRANSHOCK_SCRIPT_DIR, then <program dir>/../share/granshock
// (an installed granshock), then the source tree. Throws UserError when none has it.
std::filesystem::path study_figure_script();

// Draws the axis figures from plan.out/study.json. Throws UserError when the interpreter or
// matplotlib is missing (the caller warns and goes on) or the script fails.
void plot_study_figures(const StudyPlan& plan);

}  // namespace granshock

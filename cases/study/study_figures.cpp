#include "cases/study/study_figures.hpp"

#include <string>
#include <vector>

#include "analysis/figures.hpp"
#include "study_paths.hpp"

namespace granshock {

namespace fs = std::filesystem;

fs::path study_figure_script() {
  return figure_script("plot_study.py", GRANSHOCK_STUDY_SCRIPT_DIR);
}

void plot_study_figures(const StudyPlan& plan) {
  if (plan.spec.axes.empty()) return;
  require_plotting_python();
  std::vector<std::string> args{(plan.out / "study.json").string(), (plan.out / "figures").string(),
                                to_string(plan.spec.mode)};
  for (const StudyAxis& a : plan.spec.axes) args.push_back(a.name);
  run_figure_script(study_figure_script(), args);
}

}  // namespace granshock

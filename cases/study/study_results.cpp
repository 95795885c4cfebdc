#include "cases/study/study_results.hpp"

#include <fmt/format.h>

#include <iostream>

#include "analysis/fields_command.hpp"
#include "analysis/figures.hpp"
#include "cases/study/case_directory.hpp"
#include "cases/study/study_claims.hpp"
#include "cases/study/study_figures.hpp"
#include "cases/study/study_runner.hpp"
#include "cases/study/study_table.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

void warn(const std::string& what) {
  std::cerr << "granshock study: warning: " << what << "\n";
}

// `granshock fields DIR... --out OUT` on the finished cases: each case's fields.h5 and
// summary.json analysed again by this granshock (a case run by an older one gains the keys
// of the current analysis before it is tabulated), detachment.csv/json and, with Python,
// figures/detachment_length.png and each case's figures drawn again (the ones its run drew
// showed the analysis of that time).
void compare_finished(const StudyPlan& plan, const std::vector<fs::path>& finished, bool quiet,
                      bool figures) {
  if (finished.size() == 1) fields_command(finished, {}, FieldsCommandOptions{false, quiet});
  if (finished.size() >= 2) fields_command(finished, plan.out, FieldsCommandOptions{false, quiet});
  if (finished.size() < 2 && !quiet)
    std::cerr << "granshock study: the comparison of detachment lengths needs two finished "
                 "cases; "
              << finished.size() << " so far\n";
  if (finished.empty() || !figures) return;
  try {
    require_plotting_python();
    std::vector<std::pair<fs::path, fs::path>> runs;
    for (const fs::path& dir : finished) runs.emplace_back(dir / "fields.h5", dir / "figures");
    plot_run_figures(runs);
    if (finished.size() >= 2)
      plot_detachment_figure(plan.out / "detachment.json",
                             plan.out / "figures" / "detachment_length.png");
  } catch (const UserError& e) {
    warn(std::string("no figures: ") + e.what());
  }
}

// study.csv and study.json beside the records, where some case has one.
void copy_table_to_records(const StudyPlan& plan, const StudyTable& table) {
  const fs::path records = records_root(plan.spec, plan.out);
  std::error_code ec;
  if (!fs::is_directory(records / "cases", ec)) return;
  try {
    write_study_table(records, table);
  } catch (const UserError& e) {
    warn(std::string("the table was not copied beside the records: ") + e.what());
  }
}

}  // namespace

int write_study_results(const StudyPlan& plan, const std::map<int, std::string>& failures,
                        bool quiet, bool figures) {
  // The finished cases with their run directories are analysed again and recorded anew;
  // those known by their records alone are tabulated from the records.
  std::vector<fs::path> finished;
  std::vector<std::size_t> with_runs;
  std::vector<std::string> not_finished, from_records;
  const StudyTable states = study_table(plan, failures);
  for (std::size_t k = 0; k < plan.cases.size(); ++k) {
    const std::string status = states.rows[k]["status"].get<std::string>();
    if (status == "finished" && states.rows[k]["source"] == "record") {
      from_records.push_back(plan.cases[k].spec.name);
    } else if (status == "finished") {
      finished.push_back(plan.cases[k].dir);
      with_runs.push_back(k);
    } else {
      not_finished.push_back(plan.cases[k].spec.name + " (" + status + ")");
    }
  }
  int code = 0;
  try {
    compare_finished(plan, finished, quiet, figures);
  } catch (const UserError& e) {
    std::cerr << "granshock study: error: the comparison of the finished cases failed: " << e.what()
              << "\n";
    code = 1;
  }
  for (std::size_t k : with_runs) record_case(plan, plan.cases[k]);
  // The table from the summaries as the analysis above left them; a copy beside the
  // records, which outlive the study's directory.
  const StudyTable table = study_table(plan, failures);
  write_study_table(plan.out, table);
  copy_table_to_records(plan, table);
  if (!from_records.empty() && !quiet)
    std::cerr << fmt::format("granshock study: {} case{} from {} alone (no run directory): {}\n",
                             from_records.size(), from_records.size() == 1 ? "" : "s",
                             records_root(plan.spec, plan.out).string(),
                             fmt::join(from_records, ", "));
  write_claims(plan.out, check_paper_claims(table));
  try {
    if (figures) plot_study_figures(plan);
  } catch (const UserError& e) {
    warn(std::string("no axis figures: ") + e.what());
  }
  if (!not_finished.empty()) {
    std::cerr << fmt::format("granshock study: {} of {} cases not finished: {}\n",
                             not_finished.size(), plan.cases.size(), fmt::join(not_finished, ", "));
    code = 1;
  }
  if (!quiet)
    std::cout << fmt::format("granshock study: {}: {} of {} cases finished; table in {}\n",
                             plan.spec.name, finished.size(), plan.cases.size(),
                             (plan.out / "study.csv").string());
  return code;
}

}  // namespace granshock

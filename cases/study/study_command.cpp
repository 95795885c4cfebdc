#include "cases/study/study_command.hpp"

#include <fmt/format.h>

#include <iostream>

#include "cases/study/slurm_script.hpp"
#include "cases/study/study_directory.hpp"
#include "cases/study/study_listing.hpp"
#include "cases/study/study_plan.hpp"
#include "cases/study/study_preflight.hpp"
#include "cases/study/study_rate.hpp"
#include "cases/study/study_results.hpp"
#include "cases/study/study_runner.hpp"
#include "core/user_error.hpp"
#include "io/atomic_file.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

void check_options(const StudyOptions& o) {
  const int modes = int(o.collect) + int(o.emit.has_value()) + int(o.dry_run);
  if (modes > 1) throw UserError("--collect, --emit and --dry-run exclude each other");
  if (o.only_case && (o.collect || o.emit))
    throw UserError("--case runs one case; it does not go with --collect or --emit");
  if (o.accuracy.empty() && !o.accuracy_table.empty())
    throw UserError("--accuracy-table names the table --accuracy chooses from; give --accuracy");
}

std::vector<std::size_t> selection(const StudyPlan& plan, std::optional<long> only_case) {
  const std::size_t n = plan.cases.size();
  if (only_case && (*only_case < 0 || std::size_t(*only_case) >= n))
    throw UserError(fmt::format("--case {}: the study '{}' has {} case{} (0 to {})", *only_case,
                                plan.spec.name, n, n == 1 ? "" : "s", n - 1));
  if (only_case) return {std::size_t(*only_case)};
  std::vector<std::size_t> all(n);
  for (std::size_t k = 0; k < n; ++k) all[k] = k;
  return all;
}

int emit_slurm(const StudyPlan& plan) {
  std::error_code ec;
  const fs::path program = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw UserError("cannot find the granshock program's own path (/proc/self/exe)");
  const StudyRate rate = study_rate(plan);
  const fs::path script = plan.out / "study.slurm";
  const SlurmScript written =
      slurm_script(plan, program, rate.particle_steps_per_second, rate.source);
  claim_study_directory(plan.out, plan.spec.name);
  for (const std::string& warning : written.warnings)
    std::cerr << "granshock study: warning: " << warning << "\n";
  write_file_atomically(script, written.text);
  std::cout << fmt::format("granshock study: wrote {} ({} array tasks); submit it with sbatch\n",
                           script.string(), plan.cases.size());
  return 0;
}

bool any_case_recorded(const StudyPlan& plan) {
  for (const PlannedCase& c : plan.cases)
    if (inspect_planned_case(plan, c).from_record) return true;
  return false;
}

int collect(const StudyPlan& plan, const StudyOptions& o) {
  const StudyDirectoryState state = check_study_directory(plan.out, plan.spec.name);
  // A campaign on a fresh clone: the study's directory is gone with its runs, its records
  // are committed (docs/study.md, "Campaign records"). The table is made from them.
  if (state != StudyDirectoryState::this_study && any_case_recorded(plan))
    claim_study_directory(plan.out, plan.spec.name);
  else if (state != StudyDirectoryState::this_study)
    throw UserError(fmt::format(
        "--collect: '{}' holds no study (no {} marker) and no case has a record; run the "
        "study first, or give its directory with --out",
        plan.out.string(), kStudyMarker));
  return write_study_results(plan, {}, o.quiet, o.figures);
}

// Once the results are written: without figures, how to draw them later (one of the
// study's own lines, which --quiet keeps).
int finish(int code, const StudyOptions& o) {
  if (o.figures) return code;
  std::vector<std::string> redraw = o.redraw;
  if (redraw.empty()) {
    redraw = {"granshock", "study", o.study_file.string()};
    if (!o.out_dir.empty()) redraw.insert(redraw.end(), {"--out", o.out_dir.string()});
    for (const std::string& set : o.overrides) redraw.insert(redraw.end(), {"--set", set});
    redraw.push_back("--collect");
  }
  std::cerr << figures_skipped_note(redraw) << "\n";
  return code;
}

}  // namespace

int study_command(const StudyOptions& o) {
  check_options(o);
  StudySpec spec = load_study_file(o.study_file);
  spec.common.insert(spec.common.end(), o.overrides.begin(), o.overrides.end());
  spec.command_line_set = o.overrides;
  if (!o.accuracy.empty()) spec.accuracy = StudySpec::Accuracy{o.accuracy, o.accuracy_table};
  const StudyPlan plan = plan_study(spec, o.out_dir.empty() ? spec.out : o.out_dir);
  const std::vector<std::size_t> selected = selection(plan, o.only_case);
  if (o.collect) return finish(collect(plan, o), o);

  check_study_directory(plan.out, spec.name);
  check_case_directories(plan, selected);
  if (o.dry_run) {
    for (const PlannedCase& c : plan.cases)
      for (const std::string& w : c.warnings)
        std::cerr << "granshock study: warning: case " << c.spec.name << ": " << w << "\n";
    print_study_listing(plan, selected, std::cout);
    return 0;
  }
  if (o.emit == BatchScript::slurm) return emit_slurm(plan);

  claim_study_directory(plan.out, spec.name);
  const StudyRunResult result =
      run_study_cases(plan, selected, StudyRunOptions{o.stop_after_steps, o.quiet, o.figures});
  if (result.stopped) return result.exit_code;
  for (const auto& [index, why] : result.failures)
    std::cerr << fmt::format("granshock study: case {} (--case {}) failed: {}\n",
                             plan.cases[std::size_t(index)].spec.name, index, why);
  if (o.only_case) {
    if (!o.quiet)
      std::cerr << "granshock study: with --case the table is not built; build it with "
                   "--collect once every case has run\n";
    return result.failures.empty() ? 0 : 1;
  }
  return finish(write_study_results(plan, result.failures, o.quiet, o.figures), o);
}

}  // namespace granshock

#include "cases/study/slurm_script.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cases/study/study_cost.hpp"
#include "core/shell_text.hpp"
#include "core/user_error.hpp"

namespace granshock {

namespace fs = std::filesystem;

namespace {

// How to submit a study of more cases than Slurm's default MaxArraySize allows: parts of
// at most 1001 tasks, the first case of each part as the script's argument.
std::string array_size_warning(std::size_t n, const fs::path& script) {
  const std::size_t part = kSlurmDefaultMaxArraySize;
  const std::string name = shell_quote(script.string());
  const auto submit = [&](std::size_t first) {
    return fmt::format("sbatch --array=0-{} {} {}", std::min(part, n - first) - 1, name, first);
  };
  const std::size_t last = (n - 1) / part * part;  // the first case of the last part
  return fmt::format(
      "{} array tasks (0-{}) exceed Slurm's default MaxArraySize of {} (indices 0-{}; "
      "`scontrol show config | grep MaxArraySize` shows this cluster's); where sbatch refuses "
      "the array, submit it in parts, each part's first case as the script's argument: {}, "
      "then {}{} (docs/study.md, \"Slurm\")",
      n, n - 1, part, part - 1, submit(0), submit(part),
      last > part ? ", ... up to " + submit(last) : std::string());
}

}  // namespace

SlurmTimeLimit slurm_time_limit(double seconds) {
  const double wanted = 1.5 * seconds + 600.0;
  SlurmTimeLimit t;
  t.clamped = !(seconds >= 0) || !(wanted <= kMaxSlurmTimeLimitSeconds);
  const long minutes = long(std::ceil((t.clamped ? kMaxSlurmTimeLimitSeconds : wanted) / 60.0));
  t.text = fmt::format("{}-{:02d}:{:02d}:00", minutes / 1440, minutes / 60 % 24, minutes % 60);
  return t;
}

SlurmScript slurm_script(const StudyPlan& plan, const fs::path& program, double rate,
                         const std::string& rate_source) {
  const std::size_t n = plan.cases.size();
  double largest = 0;
  for (const PlannedCase& c : plan.cases)
    largest = std::max(largest, expected_particle_steps(c.scene));
  const fs::path study = fs::absolute(plan.spec.file).lexically_normal();
  const fs::path out = fs::absolute(plan.out).lexically_normal();
  const fs::path script = out / "study.slurm";
  for (const std::string& option : plan.spec.slurm.options)
    if (has_control_character(option) || option.rfind("--", 0) != 0)
      throw UserError(
          fmt::format("[slurm] option {}: must be one sbatch option starting with --, "
                      "without control characters",
                      shell_quote(option)));

  SlurmScript result;
  const SlurmTimeLimit limit = slurm_time_limit(largest / rate);
  if (limit.clamped)
    result.warnings.push_back(fmt::format(
        "the time limit for the largest case ({:.3g} particle-steps at {:.3g} particle-steps/s) "
        "is not below 365 days; the script asks for {}: give your own with sbatch --time=...",
        largest, rate, limit.text));
  if (n > kSlurmDefaultMaxArraySize) result.warnings.push_back(array_size_warning(n, script));

  // The command line's --set, passed on to every task and to the collect step.
  std::string sets;
  for (const std::string& o : plan.spec.command_line_set) sets += " --set " + shell_quote(o);
  // An error budget: every task chooses its case's settings as the plan did.
  if (const auto& a = plan.spec.accuracy) {
    sets += " --accuracy " + shell_quote(a->budget);
    if (!a->table.empty())
      sets +=
          " --accuracy-table " + shell_quote(fs::absolute(a->table).lexically_normal().string());
  }
  const std::string command =
      fmt::format("{} study {} --out {}{}", shell_quote(program.string()),
                  shell_quote(study.string()), shell_quote(out.string()), sets);

  std::string s = "#!/bin/bash\n";
  s += fmt::format("# granshock study {}: {} case{}, one per task of a Slurm job array\n",
                   shell_quote(plan.spec.name), n, n == 1 ? "" : "s");
  s += "# (docs/study.md, \"Slurm\"). Written by `granshock study --emit slurm`; submit it with\n";
  s += "#   sbatch " + shell_quote(script.string()) + "\n";
  s += fmt::format(
      "# Time limit: the largest case ({:.3g} particle-steps) at {:.3g} particle-steps/s ({}),\n"
      "# x1.5, plus 10 minutes{}. A task past its limit gets SIGTERM, writes its checkpoint and\n"
      "# ends with 143; submit the script again and the unfinished cases resume, the finished\n"
      "# ones are skipped. When every task has ended, build the table and figures with\n"
      "#   {} --collect\n",
      largest, rate, comment_text(rate_source), limit.clamped ? ", at most 365 days" : "", command);
  s += "#SBATCH --job-name=" + safe_name("granshock-" + plan.spec.name) + "\n";
  s += fmt::format("#SBATCH --array=0-{}\n", n - 1);
  s += fmt::format("#SBATCH --cpus-per-task={}\n", plan.spec.slurm.cpus_per_task);
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --time=" + limit.text + "\n";
  if (sbatch_plain(out.string()))
    s += "#SBATCH --output=" + (out / "slurm-%A_%a.out").string() + "\n";
  else
    s += "# (no --output: the study directory's path has characters #SBATCH lines cannot hold)\n";
  for (const std::string& option : plan.spec.slurm.options) s += "#SBATCH " + option + "\n";
  s += "\nset -euo pipefail\n";
  s += "export OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n";
  s += "export OMP_PROC_BIND=spread OMP_PLACES=threads\n";
  s += "# The case of this task: the array index plus the first case of this part of the\n";
  s += "# study (the script's argument, 0 by default).\n";
  s += "first_case=${1:-0}\n";
  s += "case $first_case in\n";
  s += "'' | *[!0-9]*)\n";
  s += "  echo \"study.slurm: the first case must be a whole number, not '$first_case'\" >&2\n";
  s += "  exit 2\n";
  s += "  ;;\n";
  s += "esac\n";
  s += "exec " + command + " --case \"$((10#$SLURM_ARRAY_TASK_ID + 10#$first_case))\"\n";
  result.text = s;
  return result;
}

}  // namespace granshock

#include "slurm_script.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "study_cost.hpp"

namespace granshock {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string slurm_time_limit(double seconds) {
  const long minutes = long(std::ceil((1.5 * std::max(0.0, seconds) + 600.0) / 60.0));
  return fmt::format("{}-{:02d}:{:02d}:00", minutes / 1440, minutes / 60 % 24, minutes % 60);
}

std::string slurm_script(const StudyPlan& plan, const fs::path& program, double rate,
                         const std::string& rate_source) {
  const std::size_t n = plan.cases.size();
  double largest = 0;
  for (const PlannedCase& c : plan.cases)
    largest = std::max(largest, expected_particle_steps(c.scene));
  const fs::path study = fs::absolute(plan.spec.file).lexically_normal();
  const fs::path out = fs::absolute(plan.out).lexically_normal();
  const bool plain_out = out.string().find_first_of(" \t%'\"\\$") == std::string::npos;

  // The command line's --set, passed on to every task and to the collect step.
  std::string sets;
  for (const std::string& o : plan.spec.command_line_set) sets += " --set " + shell_quote(o);

  std::string s = "#!/bin/bash\n";
  s += fmt::format("# granshock study '{}': {} case{}, one per task of a Slurm job array\n",
                   plan.spec.name, n, n == 1 ? "" : "s");
  s += "# (docs/study.md, \"Slurm\"). Written by `granshock study --emit slurm`; submit it with\n";
  s += "#   sbatch " + shell_quote((out / "study.slurm").string()) + "\n";
  s += fmt::format(
      "# Time limit: the largest case ({:.3g} particle-steps) at {:.3g} particle-steps/s ({}),\n"
      "# x1.5, plus 10 minutes. A task past its limit gets SIGTERM, writes its checkpoint and\n"
      "# ends with 143; submit the script again and the unfinished cases resume, the finished\n"
      "# ones are skipped. When every task has ended, build the table and figures with\n"
      "#   {} study {} --out {}{} --collect\n",
      largest, rate, rate_source, shell_quote(program.string()), shell_quote(study.string()),
      shell_quote(out.string()), sets);
  s += "#SBATCH --job-name=" + safe_name("granshock-" + plan.spec.name) + "\n";
  s += fmt::format("#SBATCH --array=0-{}\n", n - 1);
  s += fmt::format("#SBATCH --cpus-per-task={}\n", plan.spec.slurm.cpus_per_task);
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --time=" + slurm_time_limit(largest / rate) + "\n";
  if (plain_out)
    s += "#SBATCH --output=" + (out / "slurm-%A_%a.out").string() + "\n";
  else
    s += "# (no --output: the study directory's path has characters #SBATCH lines cannot hold)\n";
  for (const std::string& option : plan.spec.slurm.options) s += "#SBATCH " + option + "\n";
  s += "\nset -euo pipefail\n";
  s += "export OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n";
  s += "export OMP_PROC_BIND=spread OMP_PLACES=threads\n";
  s += fmt::format("exec {} study {} --out {}{} --case \"$SLURM_ARRAY_TASK_ID\"\n",
                   shell_quote(program.string()), shell_quote(study.string()),
                   shell_quote(out.string()), sets);
  return s;
}

}  // namespace granshock

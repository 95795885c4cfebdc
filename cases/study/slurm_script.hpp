// `granshock study STUDY.toml --emit slurm` (docs/study.md, "Slurm"): a batch script that
// runs the study as a Slurm job array, one case per array task.
#pragma once

#include <filesystem>
#include <string>

#include "study_plan.hpp"

namespace granshock {

// The script's text: #SBATCH --array=0-(N-1), --cpus-per-task and a time limit for the
// largest case at `rate` particle-steps per second, OMP_NUM_THREADS from
// SLURM_CPUS_PER_TASK, and `granshock study STUDY --out OUT --case $SLURM_ARRAY_TASK_ID`
// with absolute paths. `rate_source` says where the rate comes from (a comment).
std::string slurm_script(const StudyPlan& plan, const std::filesystem::path& program, double rate,
                         const std::string& rate_source);

// A Slurm time limit ("D-HH:MM:SS") for a case of `seconds` expected: x1.5, plus 10 minutes
// for the inflow calibration and the field analysis, in whole minutes.
std::string slurm_time_limit(double seconds);

// `text` as one word for bash (single quotes).
std::string shell_quote(const std::string& text);

}  // namespace granshock

// `granshock study STUDY.toml --emit slurm` (docs/study.md, "Slurm"): a batch script that
// runs the study as a Slurm job array, one case per array task.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cases/study/study_plan.hpp"

namespace granshock {

// Slurm's default MaxArraySize: array indices run from 0 to 1000 (slurm.conf(5)).
inline constexpr std::size_t kSlurmDefaultMaxArraySize = 1001;
// The longest time limit the script asks for: 365 days.
inline constexpr double kMaxSlurmTimeLimitSeconds = 365.0 * 86400.0;

struct SlurmScript {
  std::string text;
  std::vector<std::string> warnings;  // one line each, for stderr
};

// The script: #SBATCH --array=0-(N-1), --cpus-per-task and a time limit for the largest
// case at `rate` particle-steps per second, OMP_NUM_THREADS from SLURM_CPUS_PER_TASK, and
// `granshock study STUDY --out OUT --case K` with absolute paths, K the array index plus
// the script's first argument (0 by default; a study of more cases than the cluster's
// MaxArraySize is submitted in parts). `rate_source` says where the rate comes from (a
// comment). Warns of a clamped time limit and of more than 1001 array tasks. Every value
// written is quoted or escaped (core/shell_text.hpp); an [slurm] option holding a control
// character is a UserError.
SlurmScript slurm_script(const StudyPlan& plan, const std::filesystem::path& program, double rate,
                         const std::string& rate_source);

struct SlurmTimeLimit {
  std::string text;      // "D-HH:MM:SS"
  bool clamped = false;  // the estimate was unusable (NaN, negative) or beyond 365 days
};

// A Slurm time limit for a case of `seconds` expected: x1.5, plus 10 minutes for the inflow
// calibration and the field analysis, in whole minutes, at most 365 days.
SlurmTimeLimit slurm_time_limit(double seconds);

}  // namespace granshock

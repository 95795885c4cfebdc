// The Slurm script of `granshock study --emit slurm` (docs/study.md, "Slurm") with hostile
// values: a newline, $(...), backticks, quotes, '%', tabs and carriage returns in the study
// directory, the study file's path, the study's name, --set values, the rate's source and
// the program's path. The script is run by bash as an array task would run it, with a
// stand-in program that records its argv: nothing but the program may run, and the argv
// must arrive intact. Then the time limit's clamp and the array-size warning.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "cases/study/slurm_script.hpp"
#include "cases/study/study_cost.hpp"
#include "cases/study/study_plan.hpp"
#include "cases/study/study_rate.hpp"
#include "core/user_error.hpp"
#include "io/run_directory.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;
using granshock::testing::TempDir;
namespace fs = std::filesystem;

namespace {

// A newline followed by a command, command substitutions, quotes, sbatch's '%A', a tab,
// a carriage return and a backslash.
const std::string kHostile =
    "x\ntouch PWNED #$(touch PWNED)`touch PWNED`'\"%A\t\r\\ end\r\ntouch PWNED";

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A plan of `copies` cases (the first case of a small study, repeated).
StudyPlan small_plan(const TempDir& tmp, std::size_t copies = 1) {
  const auto base = tmp.write("small.toml", small_scene(true));
  const StudySpec spec = parse_study(
      "[study]\nname = \"t\"\nbase = \"" + base.string() + "\"\n[[case]]\nname = \"a\"\n",
      tmp.path() / "t.toml");
  StudyPlan plan = plan_study(spec, tmp.path() / "out");
  plan.cases.resize(copies, plan.cases[0]);
  return plan;
}

// A program that writes its arguments, each ended by NUL, to $ARGV_FILE.
fs::path stand_in_program(const fs::path& dir) {
  const fs::path program = dir / "granshock";
  write(program, "#!/bin/bash\nprintf '%s\\0' \"$@\" >\"$ARGV_FILE\"\n");
  fs::permissions(program, fs::perms::owner_all);
  return program;
}

std::vector<std::string> recorded_argv(const fs::path& file) {
  std::vector<std::string> argv;
  const std::string text = read(file);
  for (std::size_t start = 0, end; (end = text.find('\0', start)) != std::string::npos;
       start = end + 1)
    argv.push_back(text.substr(start, end - start));
  return argv;
}

// Runs `script` with bash as Slurm runs an array task (in its own working directory);
// returns the exit status.
int run_as_array_task(const TempDir& tmp, const fs::path& script, int task,
                      const std::string& argument = "") {
  fs::create_directories(tmp.path() / "cwd");
  const std::string command =
      "cd '" + (tmp.path() / "cwd").string() + "' && env SLURM_JOB_ID=7 SLURM_ARRAY_JOB_ID=7 " +
      "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_CPUS_PER_TASK=2 ARGV_FILE='" +
      (tmp.path() / "argv").string() + "' bash '" + script.string() + "' " + argument + " >'" +
      (tmp.path() / "log").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

TEST(SlurmScript, HostileValuesStayQuotedAndTheArgvArrivesIntact) {
  TempDir tmp;
  StudyPlan plan = small_plan(tmp, 4);
  plan.spec.name = kHostile;
  plan.spec.file = tmp.path() / ("study" + kHostile) / "s.toml";
  plan.out = tmp.path() / ("out" + kHostile);
  plan.spec.command_line_set = {"time.duration=0.004" + kHostile, "a='b'", "c=$(touch PWNED)",
                                "d=\\'"};
  plan.spec.slurm.options = {"--partition=short", "--comment=$(touch PWNED)`touch PWNED`"};
  const fs::path program = stand_in_program(tmp.path() / ("bin" + kHostile));

  const SlurmScript written = slurm_script(plan, program, 1e8, "measured" + kHostile);
  const fs::path script = tmp.path() / "study.slurm";
  write(script, written.text);
  EXPECT_TRUE(written.warnings.empty());

  // No raw control character but the line ends: a comment stays one line, and sbatch
  // refuses a script with a carriage return.
  const auto control = std::count_if(written.text.begin(), written.text.end(), [](char c) {
    return c != '\n' && (static_cast<unsigned char>(c) < 0x20 || c == 0x7f);
  });
  EXPECT_EQ(control, 0) << "control characters in the script:\n" << written.text;
  EXPECT_EQ(std::system(("bash -n '" + script.string() + "'").c_str()), 0);

  // sbatch reads #SBATCH lines up to the first command: every one of them comes before it.
  const std::vector<std::string> lines = lines_of(written.text);
  std::size_t first_command = 0;
  while (first_command < lines.size() &&
         (lines[first_command].empty() || lines[first_command][0] == '#'))
    ++first_command;
  std::vector<std::string> directives;
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (lines[k].rfind("#SBATCH", 0) == 0) {
      EXPECT_LT(k, first_command) << lines[k] << " comes after a command";
      directives.push_back(lines[k]);
    }
  EXPECT_EQ(directives,
            (std::vector<std::string>{"#SBATCH --job-name=granshock-x-touch-PWNED-touch-PWNED-"
                                      "touch-PWNED-A-end-touch-PWNED",
                                      "#SBATCH --array=0-3", "#SBATCH --cpus-per-task=4",
                                      "#SBATCH --ntasks=1", "#SBATCH --time=0-00:11:00",
                                      "#SBATCH --partition=short",
                                      "#SBATCH --comment=$(touch PWNED)`touch PWNED`"}))
      << "no --output: the study directory's path cannot stand on an #SBATCH line";

  EXPECT_EQ(run_as_array_task(tmp, script, 2), 0) << read(tmp.path() / "log");
  for (const auto& entry : fs::recursive_directory_iterator(tmp.path()))
    EXPECT_NE(entry.path().filename(), "PWNED") << entry.path() << ": a command ran";
  const std::vector<std::string> expected = {"study",  fs::absolute(plan.spec.file).string(),
                                             "--out",  plan.out.string(),
                                             "--set",  plan.spec.command_line_set[0],
                                             "--set",  "a='b'",
                                             "--set",  "c=$(touch PWNED)",
                                             "--set",  "d=\\'",
                                             "--case", "2"};
  EXPECT_EQ(recorded_argv(tmp.path() / "argv"), expected);
}

TEST(SlurmScript, AnOptionWithAControlCharacterIsRefused) {
  TempDir tmp;
  StudyPlan plan = small_plan(tmp);
  plan.spec.slurm.options = {"--partition=short\ntouch PWNED"};
  EXPECT_THROW(slurm_script(plan, "/bin/granshock", 1e8, "r"), UserError);
  plan.spec.slurm.options = {"--comment=a\rb"};
  EXPECT_THROW(slurm_script(plan, "/bin/granshock", 1e8, "r"), UserError);
}

TEST(SlurmScript, TimeLimitIsClampedTo365DaysAndNeverNegative) {
  EXPECT_EQ(slurm_time_limit(0).text, "0-00:10:00");
  EXPECT_FALSE(slurm_time_limit(0).clamped);
  EXPECT_EQ(slurm_time_limit(3600).text, "0-01:40:00");  // x1.5 + 10 min
  EXPECT_EQ(slurm_time_limit(86400).text, "1-12:10:00");
  const double just_below = (kMaxSlurmTimeLimitSeconds - 600) / 1.5;
  EXPECT_EQ(slurm_time_limit(just_below).text, "365-00:00:00");
  EXPECT_FALSE(slurm_time_limit(just_below).clamped);
  for (double bad : {just_below * 1.01, 1e300, HUGE_VAL, std::nan(""), -1.0, -1e300, -HUGE_VAL}) {
    const SlurmTimeLimit t = slurm_time_limit(bad);
    EXPECT_EQ(t.text, "365-00:00:00") << bad;
    EXPECT_TRUE(t.clamped) << bad;
  }
}

TEST(SlurmScript, ARunReportingAnAbsurdDurationGivesAClampedLimitAndAWarning) {
  TempDir tmp;
  const StudyPlan plan = small_plan(tmp);
  write(plan.cases[0].dir / kRunMarker, "format = 1\n");
  write(plan.cases[0].dir / "summary.json",
        R"({"completed": true, "steps": 50000, "wall_seconds": 1e300, "fields_bins": 40})");
  const StudyRate rate = study_rate(plan);
  const SlurmScript written =
      slurm_script(plan, "/bin/granshock", rate.particle_steps_per_second, rate.source);
  EXPECT_NE(written.text.find("\n#SBATCH --time=365-00:00:00\n"), std::string::npos)
      << written.text;
  ASSERT_EQ(written.warnings.size(), 1u);
  EXPECT_NE(written.warnings[0].find("is not below 365 days"), std::string::npos)
      << written.warnings[0];

  // A duration no run reports is not a measurement: the reference rate is used.
  for (const char* wall : {"-5", "0", "1e999"}) {
    write(
        plan.cases[0].dir / "summary.json",
        std::string(R"({"completed": true, "steps": 50000, "fields_bins": 40, "wall_seconds": )") +
            wall + "}");
    EXPECT_EQ(study_rate(plan).particle_steps_per_second, kReferenceRate) << wall;
  }
}

TEST(SlurmScript, MoreTasksThanMaxArraySizeWarnAndTheScriptRunsInParts) {
  TempDir tmp;
  EXPECT_TRUE(slurm_script(small_plan(tmp, 1001), "/bin/g", 1e8, "r").warnings.empty());

  const StudyPlan plan = small_plan(tmp, 10000);
  const fs::path program = stand_in_program(tmp.path() / "bin");
  const SlurmScript written = slurm_script(plan, program, 1e8, "r");
  const fs::path script = tmp.path() / "out" / "study.slurm";
  write(script, written.text);
  EXPECT_NE(written.text.find("\n#SBATCH --array=0-9999\n"), std::string::npos);
  ASSERT_EQ(written.warnings.size(), 1u);
  const std::string& warning = written.warnings[0];
  EXPECT_EQ(warning.find('\n'), std::string::npos);
  EXPECT_NE(warning.find("10000 array tasks (0-9999) exceed Slurm's default MaxArraySize of 1001"),
            std::string::npos)
      << warning;

  // The parts the warning names cover cases 0 to 9999, each once.
  const std::regex part("sbatch --array=0-([0-9]+) '[^']*' ([0-9]+)");
  std::vector<std::pair<long, long>> parts;  // first case, tasks
  for (auto it = std::sregex_iterator(warning.begin(), warning.end(), part);
       it != std::sregex_iterator(); ++it)
    parts.emplace_back(std::stol((*it)[2]), std::stol((*it)[1]) + 1);
  ASSERT_EQ(parts.size(), 3u) << warning;  // the first, the second, the last
  EXPECT_EQ(parts[0], std::make_pair(0L, 1001L));
  EXPECT_EQ(parts[1], std::make_pair(1001L, 1001L));
  EXPECT_EQ(parts[2], std::make_pair(9009L, 991L));
  EXPECT_NE(warning.find("... up to"), std::string::npos);
  for (const auto& [first, tasks] : parts)
    for (long task : {0L, tasks - 1}) {
      ASSERT_EQ(run_as_array_task(tmp, script, int(task), std::to_string(first)), 0)
          << read(tmp.path() / "log");
      const std::vector<std::string> argv = recorded_argv(tmp.path() / "argv");
      ASSERT_FALSE(argv.empty());
      EXPECT_EQ(argv.back(), std::to_string(first + task));
    }

  // A leading zero is decimal, not octal; anything but digits is refused before the run.
  EXPECT_EQ(run_as_array_task(tmp, script, 3, "010"), 0);
  EXPECT_EQ(recorded_argv(tmp.path() / "argv").back(), "13");
  fs::remove(tmp.path() / "argv");
  EXPECT_EQ(run_as_array_task(tmp, script, 3, "'$(touch PWNED)'"), 2);
  EXPECT_FALSE(fs::exists(tmp.path() / "argv")) << "the program ran";
  EXPECT_FALSE(fs::exists(tmp.path() / "cwd" / "PWNED"));
  EXPECT_NE(read(tmp.path() / "log").find("the first case must be a whole number"),
            std::string::npos);
}

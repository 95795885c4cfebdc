#include "study_figures.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <string>
#include <vector>

#include "figures.hpp"
#include "study_paths.hpp"
#include "user_error.hpp"

extern char** environ;

namespace granshock {

namespace fs = std::filesystem;

namespace {

// Runs args[0] with args, without a shell; its exit status, or -1 when it could not start
// or was killed by a signal.
int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

fs::path study_figure_script() {
  const std::string name = "plot_study.py";
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("GRANSHOCK_SCRIPT_DIR"); env != nullptr && *env != '\0')
    candidates.push_back(fs::path(env) / name);
  std::error_code ec;
  if (const fs::path self = fs::read_symlink("/proc/self/exe", ec); !ec)
    candidates.push_back(self.parent_path() / ".." / GRANSHOCK_STUDY_INSTALL_DATADIR / name);
  candidates.push_back(fs::path(GRANSHOCK_STUDY_SCRIPT_DIR) / name);
  for (const fs::path& p : candidates)
    if (fs::is_regular_file(p, ec)) return p;
  std::string tried;
  for (const fs::path& p : candidates) tried += (tried.empty() ? "" : ", ") + p.string();
  throw UserError("cannot find the figure script " + name + " (looked at " + tried +
                  "); set GRANSHOCK_SCRIPT_DIR to the folder that holds it");
}

void plot_study_figures(const StudyPlan& plan) {
  if (plan.spec.axes.empty()) return;
  require_plotting_python();
  std::vector<std::string> args{plotting_python().string(), study_figure_script().string(),
                                (plan.out / "study.json").string(), (plan.out / "figures").string(),
                                to_string(plan.spec.mode)};
  for (const StudyAxis& a : plan.spec.axes) args.push_back(a.name);
  const int status = run_program(args);
  if (status != 0)
    throw UserError("plot_study.py failed (exit status " + std::to_string(status) +
                    ") drawing the study's figures; its message is above");
}

}  // namespace granshock

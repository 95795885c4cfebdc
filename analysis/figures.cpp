#include "analysis/figures.hpp"
#include "fields_paths.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/user_error.hpp"
#include "io/atomic_file.hpp"

extern char** environ;

namespace granshock {

namespace fs = std::filesystem;

namespace {

// Runs argv[0] with argv, without a shell; returns its exit status (-1: could not start or
// killed by a signal). quiet sends its stdout and stderr to /dev/null.
int run_process(const std::vector<std::string>& args, bool quiet) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

fs::path program_directory() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self.parent_path();
}

fs::path plotting_python() {
  const char* env = std::getenv("GRANSHOCK_PYTHON");
  return env != nullptr && *env != '\0' ? fs::path(env) : fs::path("/usr/bin/python3");
}

fs::path figure_script(const std::string& name) {
  return figure_script(name, GRANSHOCK_FIELDS_SCRIPT_DIR);
}

fs::path figure_script(const std::string& name, const fs::path& source_dir) {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("GRANSHOCK_SCRIPT_DIR"); env != nullptr && *env != '\0')
    candidates.push_back(fs::path(env) / name);
  if (const fs::path dir = program_directory(); !dir.empty())
    candidates.push_back(dir / ".." / GRANSHOCK_FIELDS_INSTALL_DATADIR / name);
  candidates.push_back(source_dir / name);
  std::error_code ec;
  for (const fs::path& p : candidates)
    if (fs::is_regular_file(p, ec)) return p;
  std::string tried;
  for (const fs::path& p : candidates) tried += (tried.empty() ? "" : ", ") + p.string();
  throw UserError("cannot find the figure script " + name + " (looked at " + tried +
                  "); set GRANSHOCK_SCRIPT_DIR to the folder that holds it");
}

void run_figure_script(const fs::path& script, const std::vector<std::string>& script_args) {
  std::vector<std::string> args{plotting_python().string(), script.string()};
  args.insert(args.end(), script_args.begin(), script_args.end());
  const int status = run_process(args, false);
  if (status != 0)
    throw UserError(script.filename().string() + " failed (exit status " + std::to_string(status) +
                    ") drawing the figures; its message is above");
}

void require_plotting_python() {
  const fs::path python = plotting_python();
  const std::string install =
      "; the figures need Python 3 with matplotlib, h5py and numpy (Debian: apt-get install "
      "python3 "
      "python3-matplotlib python3-h5py), or GRANSHOCK_PYTHON naming an interpreter that has them";
  std::error_code ec;
  if (!fs::exists(python, ec))
    throw UserError("no Python interpreter at " + python.string() + install);
  if (run_process({python.string(), "-c", "import matplotlib, h5py, numpy"}, true) != 0)
    throw UserError(python.string() + " cannot import matplotlib, h5py and numpy" + install);
}

// The figures' directory is one granshock makes itself, never a link to elsewhere; the
// scripts write each PNG under a new temporary name and rename it (figure_files.py).
void plot_run_figures(const fs::path& fields_h5, const fs::path& figures_dir) {
  plot_run_figures({{fields_h5, figures_dir}});
}

void plot_run_figures(const std::vector<std::pair<fs::path, fs::path>>& runs) {
  if (runs.empty()) return;
  std::vector<std::string> args;
  for (const auto& [fields_h5, figures_dir] : runs) {
    make_real_directory(figures_dir);
    args.insert(args.end(), {fields_h5.string(), figures_dir.string()});
  }
  run_figure_script(figure_script("plot_fields.py"), args);
}

void plot_detachment_figure(const fs::path& table_json, const fs::path& png) {
  make_real_directory(png.parent_path());
  run_figure_script(figure_script("plot_detachment.py"), {table_json.string(), png.string()});
}

}  // namespace granshock

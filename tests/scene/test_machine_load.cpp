// The machine's load at the start of a run (machine_load.hpp): tasks' states from /proc,
// and a busy process beside this one seen as load.
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cases/bow_shock/machine_load.hpp"

namespace granshock {
namespace {

TEST(MachineLoad, TheStateIsReadFromATaskStatLine) {
  // A command name with spaces and parentheses.
  EXPECT_EQ(task_state("4242 (my (odd) prog) R 1 4242 4242 0 -1 4194560 120 0 0 0 37 2 0 0 25 5 1"),
            'R');
  EXPECT_EQ(task_state("8 (bash) S 1 8 8 0 -1 0 0 0 0 0 0 0 0 0 20 0 1 0 1"), 'S');
  EXPECT_EQ(task_state("no parenthesis here"), std::nullopt);
  EXPECT_EQ(task_state("9 (ends here)"), std::nullopt);
}

TEST(MachineLoad, ThreadsWaitWhenTheOthersLeaveTooFewCpus) {
  EXPECT_FALSE(threads_would_wait({0, 2}, 2));  // idle 2-core laptop
  EXPECT_TRUE(threads_would_wait({1, 2}, 2));   // one busy process beside 2 threads
  EXPECT_FALSE(threads_would_wait({1, 4}, 2));  // room left on 4 cores
  EXPECT_TRUE(threads_would_wait({3, 4}, 2));
}

// The load with a busy child, this process and the child restricted to one CPU.
std::optional<MachineLoad> load_beside_a_busy_child() {
  cpu_set_t old_set;
  if (sched_getaffinity(0, sizeof(old_set), &old_set) != 0) return std::nullopt;
  int cpu = 0;
  while (!CPU_ISSET(cpu, &old_set)) ++cpu;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  if (sched_setaffinity(0, sizeof(one), &one) != 0) return std::nullopt;
  const pid_t child = fork();
  if (child == 0) {
    for (volatile unsigned long k = 0;; k = k + 1) {
    }
  }
  usleep(50000);  // the child runs
  const std::optional<MachineLoad> load = measure_machine_load();
  if (child > 0) {
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
  }
  sched_setaffinity(0, sizeof(old_set), &old_set);
  return load;
}

// A busy process on the one CPU this process may use: 2 threads would wait.
TEST(MachineLoad, ABusyProcessIsSeen) {
  const std::optional<MachineLoad> load = load_beside_a_busy_child();
  ASSERT_TRUE(load.has_value());
  EXPECT_EQ(load->cpus, 1);
  EXPECT_GE(load->others_running, 1);
  EXPECT_TRUE(threads_would_wait(*load, 2));
}

// A /proc tree written here: the runnable tasks of other processes count, niced ones too
// (their time slices stall the threads' barriers as well), this process's and sleeping
// ones do not, and a process without a task list (ended while read) is skipped.
TEST(MachineLoad, OthersRunningCountsTheRunnableTasksOfOtherProcesses) {
  namespace fs = std::filesystem;
  const fs::path proc = fs::path(testing::TempDir()) / "granshock_fake_proc";
  fs::remove_all(proc);
  const auto task = [&](const std::string& pid, const std::string& tid, char state, int nice) {
    fs::create_directories(proc / pid / "task" / tid);
    std::ofstream(proc / pid / "task" / tid / "stat")
        << tid << " (a (b) c) " << state << " 1 1 1 0 -1 0 0 0 0 0 5 1 0 0 20 " << nice
        << " 1 0 100\n";
  };
  task("100", "100", 'R', 0);   // another process, running: 1
  task("100", "101", 'R', 0);   // its second thread, running: 2
  task("100", "102", 'S', 0);   // sleeping
  task("200", "200", 'R', 15);  // a niced build: 3
  task("300", "300", 'D', 0);   // waiting for the disk
  task("42", "42", 'R', 0);     // this process
  task("42", "43", 'R', 0);
  fs::create_directories(proc / "500");  // ended: no task list
  fs::create_directories(proc / "sys");  // not a process
  EXPECT_EQ(others_running(proc.string(), 42), 3);
  EXPECT_EQ(others_running((proc / "missing").string(), 42), std::nullopt);
  fs::remove_all(proc);
}

}  // namespace
}  // namespace granshock

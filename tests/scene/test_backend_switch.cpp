// The choice between threads and one thread from measured rates (backend_switch.hpp), on
// simulated machines: the rates of each backend are given as functions of wall time. As in
// the run loop, a slice is a number of steps sized from the rate of the slice before it
// (progress_meter.hpp), so a slice on a backend that has become slower lasts longer.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "cases/bow_shock/backend_switch.hpp"

namespace granshock {
namespace {

// Particle-steps per second of each backend at wall time t.
struct Machine {
  std::function<double(double)> threads, one_thread;
};

struct Outcome {
  double wall = 0, particle_steps = 0, seconds_on_one_thread = 0;
  double switched_to_one_thread_at = -1, back_to_threads_at = -1;
};

Outcome simulate(BackendSwitch& s, const Machine& m, double until) {
  Outcome o;
  double last_rate = 0;
  while (o.wall < until) {
    const bool one = s.current() == Backend::serial;
    const double rate = one ? m.one_thread(o.wall) : m.threads(o.wall);
    const double work = (last_rate > 0 ? last_rate : rate) * s.slice_seconds();
    const double seconds = work / rate;
    last_rate = rate;
    o.wall += seconds;
    o.particle_steps += work;
    if (one) o.seconds_on_one_thread += seconds;
    const Backend before = s.current();
    const long switches = s.switches();
    s.observe(work, seconds);
    if (s.switches() == switches) continue;
    // A try that won: on one thread (a move there) or on the threads (a move back).
    if (before == Backend::serial && o.switched_to_one_thread_at < 0)
      o.switched_to_one_thread_at = o.wall;
    if (before == Backend::default_space &&
        (o.switched_to_one_thread_at >= 0 || s.started_on_one_thread()) && o.back_to_threads_at < 0)
      o.back_to_threads_at = o.wall;
  }
  return o;
}

// An idle 2-core machine: the threads at 1.8x one thread. The tries of one thread cost
// under 2 % of the run, and the run stays on the threads.
TEST(BackendSwitch, AnIdleMachineKeepsTheThreads) {
  BackendSwitch s;
  const Machine idle{[](double) { return 2.0e8; }, [](double) { return 1.1e8; }};
  const Outcome o = simulate(s, idle, 600);
  EXPECT_EQ(s.current(), Backend::default_space);
  EXPECT_EQ(s.switches(), 0);
  EXPECT_GT(s.tries(), 3);
  EXPECT_LT(o.seconds_on_one_thread / o.wall, 0.02);
  // Against the threads alone: at least 0.98 of their particle-steps.
  EXPECT_GT(o.particle_steps / (2.0e8 * o.wall), 0.98);
  EXPECT_DOUBLE_EQ(s.threads_rate(), 2.0e8);
  EXPECT_DOUBLE_EQ(s.one_thread_rate(), 1.1e8);
}

// Beside a busy process, 2 threads ran 35 times slower than one thread: the run moves to
// one thread at the first try and gets most of one thread's rate over the run.
TEST(BackendSwitch, ABusyMachineMovesToOneThread) {
  BackendSwitch s;
  const Machine busy{[](double) { return 3.6e6; }, [](double) { return 1.25e8; }};
  const Outcome o = simulate(s, busy, 600);
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_GT(o.switched_to_one_thread_at, 0);
  EXPECT_LT(o.switched_to_one_thread_at, 1.5);
  // The tries of the threads (at doubling gaps) cost a few percent at most.
  EXPECT_GT(o.particle_steps / (1.25e8 * o.wall), 0.9);
}

// A short run beside a busy process (the default scene's 0.03 s, about 8 s on one thread):
// the first slice is discarded (start-up), the first try comes after a 0.5 s window and
// lasts one try window, and a try of the collapsed threads lasts about one try window too.
// The run keeps 0.85 of one thread's rate: what is lost is the first 0.85 s on the threads.
TEST(BackendSwitch, AShortRunBesideABusyProcessKeepsMostOfOneThread) {
  BackendSwitch s;
  const Machine busy{[](double) { return 3.6e6; }, [](double) { return 1.25e8; }};
  const Outcome o = simulate(s, busy, 8);
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_LT(o.switched_to_one_thread_at, 1.0);
  EXPECT_GT(o.particle_steps / (1.25e8 * o.wall), 0.85);
}

// Load that arrives during the run: the rate's drop starts a try at once, long before the
// next regular one (60 s apart by then). The slice under way when the load came was sized
// at the idle rate and lasts 55 times longer (0.25 s x 2e8 / 3.6e6 = 14 s): that, a
// window and a try, and the run is on one thread.
TEST(BackendSwitch, LoadArrivingMidRunIsAnsweredAtOnce) {
  BackendSwitch s;
  const Machine later{[](double t) { return t < 300 ? 2.0e8 : 3.6e6; },
                      [](double t) { return t < 300 ? 1.1e8 : 1.25e8; }};
  const Outcome o = simulate(s, later, 400);
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_GE(o.switched_to_one_thread_at, 300);
  EXPECT_LT(o.switched_to_one_thread_at, 300 + 0.25 * 2.0e8 / 3.6e6 + 2);
}

// Load that lifts: the run goes back to the threads within the first gap after the move.
TEST(BackendSwitch, LoadLiftingReturnsToTheThreads) {
  BackendSwitch s;
  const Machine lifting{[](double t) { return t < 10 ? 3.6e6 : 2.0e8; },
                        [](double) { return 1.1e8; }};
  const Outcome o = simulate(s, lifting, 60);
  EXPECT_EQ(s.current(), Backend::default_space);
  ASSERT_GT(o.switched_to_one_thread_at, 0);
  EXPECT_GT(o.back_to_threads_at, 10);
  EXPECT_LT(o.back_to_threads_at, 10 + BackendSwitchPolicy{}.longest_gap_s);
}

// Rates that scatter by +-15 % from window to window (a noisy shared machine) with the
// threads 1.8x faster: no move, and no try more often than the doubling gaps allow (0.5,
// 1, 2, 4, 8, 16 and 32 s, then every 60 s: 15 tries in 600 s).
TEST(BackendSwitch, NoiseDoesNotMoveTheRun) {
  BackendSwitch s;
  const Machine noisy{[](double t) { return 2.0e8 * (1 + 0.15 * std::sin(7.3 * t)); },
                      [](double t) { return 1.1e8 * (1 + 0.15 * std::cos(5.1 * t)); }};
  simulate(s, noisy, 600);
  EXPECT_EQ(s.switches(), 0);
  EXPECT_LE(s.tries(), 15);
}

// A try lasts one short window: its slices are a fraction of the usual ones.
TEST(BackendSwitch, TriesUseShortSlices) {
  BackendSwitch s;
  EXPECT_DOUBLE_EQ(s.slice_seconds(), 0.25);
  double wall = 0;
  while (s.tries() == 0) {
    s.observe(2e8 * 0.25, 0.25);
    wall += 0.25;
  }
  EXPECT_GE(wall, BackendSwitchPolicy{}.first_gap_s);
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_LT(s.slice_seconds(), 0.05);
}

// A run that saw the machine busy at its start (machine_load.hpp) starts on one thread:
// the same short run as above then keeps nearly all of one thread's rate, against 0.85
// when it starts on the collapsed threads, and it tries the threads only after the gap
// that follows a move.
TEST(BackendSwitch, AStartOnOneThreadKeepsOneThreadsRateFromTheStart) {
  BackendSwitch s;
  s.start_on_one_thread();
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_TRUE(s.started_on_one_thread());
  const Machine busy{[](double) { return 3.6e6; }, [](double) { return 1.25e8; }};
  const Outcome o = simulate(s, busy, 8);
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_EQ(s.switches(), 0);
  EXPECT_GT(o.particle_steps / (1.25e8 * o.wall), 0.95);
  EXPECT_GT(o.seconds_on_one_thread / o.wall, 0.95);
}

// A start on one thread that was wrong (the load was gone a moment later): the run is back
// on the threads after the gap that follows a move.
TEST(BackendSwitch, AStartOnOneThreadOnAnIdleMachineReturnsToTheThreads) {
  BackendSwitch s;
  s.start_on_one_thread();
  const Machine idle{[](double) { return 2.0e8; }, [](double) { return 1.1e8; }};
  const Outcome o = simulate(s, idle, 60);
  EXPECT_EQ(s.current(), Backend::default_space);
  EXPECT_GT(o.back_to_threads_at, 0);
  EXPECT_LT(o.back_to_threads_at, BackendSwitchPolicy{}.gap_after_move_s + 1.0);
}

// On one thread beside load that /proc still shows (set_threads_free says no), the tries
// of the threads are skipped: no move after the start, nearly all of one thread's rate,
// and the skipped tries at the doubling gaps (2, 4, 8, 16 and 30 s of a 60 s run).
TEST(BackendSwitch, TriesAreSkippedWhileTheMachineStaysBusy) {
  BackendSwitch s;
  int asked = 0;
  s.set_threads_free([&asked] {
    ++asked;
    return false;
  });
  s.start_on_one_thread();
  const Machine busy{[](double) { return 3.6e6; }, [](double) { return 1.25e8; }};
  const Outcome o = simulate(s, busy, 60);
  EXPECT_EQ(s.current(), Backend::serial);
  EXPECT_EQ(s.tries(), 0);
  EXPECT_EQ(s.switches(), 0);
  EXPECT_EQ(s.skipped_tries(), asked);
  EXPECT_GE(asked, 4);
  EXPECT_GT(o.particle_steps / (1.25e8 * o.wall), 0.999);
}

// Once /proc shows the CPUs free again the threads are tried, and taken back where they
// are faster.
TEST(BackendSwitch, TheThreadsAreTriedOnceTheMachineIsFree) {
  BackendSwitch s;
  double now = 0;
  s.set_threads_free([&now] { return now > 10; });
  s.start_on_one_thread();
  const Machine lifting{[](double t) { return t < 10 ? 3.6e6 : 2.0e8; },
                        [](double) { return 1.1e8; }};
  Outcome o;
  while (o.wall < 60) {  // simulate() with the clock shared with the load check
    const bool one = s.current() == Backend::serial;
    const double rate = one ? lifting.one_thread(o.wall) : lifting.threads(o.wall);
    const double seconds = s.slice_seconds();
    o.wall += seconds;
    now = o.wall;
    const Backend before = s.current();
    const long switches = s.switches();
    s.observe(rate * seconds, seconds);
    if (s.switches() != switches && before == Backend::default_space && o.back_to_threads_at < 0)
      o.back_to_threads_at = o.wall;
  }
  EXPECT_EQ(s.current(), Backend::default_space);
  EXPECT_GT(o.back_to_threads_at, 10);
  EXPECT_LT(o.back_to_threads_at, 10 + 16 + 1);  // within the gap of the time it lifted
  EXPECT_GE(s.skipped_tries(), 1);
}

}  // namespace
}  // namespace granshock

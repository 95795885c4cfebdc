// The progress meter's step rate (cases/bow_shock/progress_meter.hpp) sizes the time loop's
// wall-clock slices. It must be measured from observe() alone: a --quiet run prints no
// progress line, and when only the printed report measured it, a quiet run's slices stayed
// at the 50-step fallback for the whole run (an unfused chunk end every 50 steps).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "cases/bow_shock/progress_meter.hpp"

using namespace granshock;

TEST(ProgressMeter, FallsBackUntilARateIsMeasured) {
  ProgressMeter meter(0, 1000000, 5.0, stderr);
  EXPECT_EQ(meter.steps_per(0.25, 50), 50);
}

TEST(ProgressMeter, LearnsTheRateFromObservationsWithoutReports) {
  ProgressMeter meter(100, 1000000, 5.0, stderr);
  const auto pause = std::chrono::duration<double>(4 * ProgressMeter::rate_window_s);
  std::this_thread::sleep_for(pause);
  meter.observe(100 + 8000);
  // 8000 steps in at least 0.08 s: at most 1e5 steps/s, so at most 25000 in 0.25 s; the
  // sleep may last longer than asked on a loaded machine, never shorter.
  const long slice = meter.steps_per(0.25, 50);
  EXPECT_NE(slice, 50);
  EXPECT_LE(slice, 25000);
  EXPECT_GT(slice, 0);
}

// The prefill's line (a prefill of 3e7 particles ran 14 minutes without one): slabs filled,
// the share done, particles placed and the time left, in the run's form.
TEST(ProgressMeter, PrefillLineSaysSlabsParticlesAndTimeLeft) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  ProgressMeter meter(0, 0, 5.0, out);
  meter.report_prefill(25, 100, 12345);
  std::rewind(out);
  char line[256] = {};
  ASSERT_NE(std::fgets(line, sizeof line, out), nullptr);
  std::fclose(out);
  const std::string text = line;
  EXPECT_EQ(text.rfind("prefill 25/100 slabs (25.0%)  particles 12345  ETA ", 0), 0u) << text;
  EXPECT_EQ(text.back(), '\n');
}

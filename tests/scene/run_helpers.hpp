// Helpers for tests that run `granshock run` in-process: options for a scene file and an
// output directory, and summary.json as JSON.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cases/bow_shock/run_command.hpp"
#include "core/solver_state.hpp"

namespace granshock::testing {

inline RunOptions run_options(const std::filesystem::path& scene, const std::filesystem::path& out,
                              std::vector<std::string> sets = {}) {
  RunOptions o;
  o.scene_file = scene;
  o.out_dir = out;
  o.overrides = std::move(sets);
  o.quiet = true;
  // On the threads throughout: beside other tests (ctest -j) the backend switch may move a
  // run to one thread, which sums the time series' energies in another order (the
  // trajectory stays bitwise: docs/benchmarks.md, "A busy machine"), and the tests that
  // compare two runs' series bit for bit would fail by chance. The device-path build's
  // RunResume test did.
  o.backend_switch = BackendSwitchMode::off;
  return o;
}

// The two runs a bitwise-resume test compares: options_for("straight") run through, and
// options_for("split") stopped after `stop_after` steps, then resumed with the same options.
template <class OptionsFor>
void run_straight_and_split(OptionsFor&& options_for, long stop_after) {
  ASSERT_EQ(run_scene(options_for("straight")), 0);
  RunOptions first = options_for("split");
  first.stop_after_steps = stop_after;
  ASSERT_EQ(run_scene(first), 0);
  RunOptions second = options_for("split");
  second.resume = true;
  ASSERT_EQ(run_scene(second), 0);
}

// Two runs' states, the second bitwise the first (`what` names the difference tested).
inline void expect_bitwise_equal_states(const SolverState& a, const SolverState& b,
                                        const std::string& what) {
  EXPECT_EQ(b.step, a.step) << what;
  EXPECT_EQ(a.id, b.id) << what;
  EXPECT_EQ(a.position, b.position) << what << ": the positions differ";
  EXPECT_EQ(a.velocity, b.velocity) << what;
  EXPECT_EQ(a.angular_velocity, b.angular_velocity) << what;
  EXPECT_EQ(a.force, b.force) << what;
}

inline nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace granshock::testing

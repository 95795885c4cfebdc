// A small `granshock run` stopped at a checkpoint, for the tests that damage checkpoints:
// fresh copies of its run directory to resume, and the uninterrupted run's checkpoint a
// few steps later to compare a resumed run with.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cases/bow_shock/run_command.hpp"
#include "io/checkpoint_file.hpp"
#include "scene_fixtures.hpp"

namespace granshock::testing {

class StoppedRun {
 public:
  // Runs `scene` with `sets` to step `stop_at` (the checkpoint to damage); the run
  // without interruption to stop_at + more_steps follows when first asked for.
  StoppedRun(const std::string& scene, std::vector<std::string> sets, long stop_at, long more_steps)
      : sets_(std::move(sets)), stop_at_(stop_at), more_steps_(more_steps) {
    scene_ = tmp_.write("scene.toml", scene);
    run_fresh(tmp_.path() / "base", stop_at);
  }

  std::filesystem::path base() const { return tmp_.path() / "base"; }
  std::filesystem::path reference_checkpoint() const {
    const auto dir = tmp_.path() / "reference";
    if (!std::filesystem::exists(dir)) run_fresh(dir, stop_at_ + more_steps_);
    return dir / "checkpoint.h5";
  }

  // A fresh copy of the stopped run directory (resuming changes run.h5).
  std::filesystem::path copy(const std::string& name) const {
    const auto dir = tmp_.path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::copy(base(), dir, std::filesystem::copy_options::recursive);
    return dir;
  }

  // Resumes `dir` for more_steps steps (it stops with a checkpoint, before the end).
  int resume(const std::filesystem::path& dir) const {
    RunOptions o = options(dir);
    o.resume = true;
    o.stop_after_steps = more_steps_;
    return run_scene(o);
  }

 private:
  RunOptions options(const std::filesystem::path& dir) const {
    RunOptions o;
    o.scene_file = scene_;
    o.out_dir = dir;
    o.overrides = sets_;
    o.quiet = true;
    return o;
  }
  void run_fresh(const std::filesystem::path& dir, long steps) const {
    RunOptions o = options(dir);
    o.stop_after_steps = steps;
    if (run_scene(o) != 0) throw std::runtime_error("the stopped run failed");
  }

  TempDir tmp_;
  std::filesystem::path scene_;
  std::vector<std::string> sets_;
  long stop_at_, more_steps_;
};

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Field sums are accumulated with atomic adds whose order varies between runs with more
// than one thread (docs/design.md, "The solver"), so two runs that are bitwise the same
// particle for particle agree on them to round-off only: within 1e-12 of the largest sum.
// A damaged value cannot hide in that margin: the checkpoint's checksum refuses any
// changed byte (docs/output_format.md).
inline bool same_sums(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  double scale = 0;
  for (double v : a) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(std::abs(a[i] - b[i]) <= 1e-12 * scale)) return false;
  return true;
}

// Whether two checkpoints hold bitwise the same run (wall time aside; field sums to
// round-off).
inline bool same_run(const std::filesystem::path& a, const std::filesystem::path& b) {
  CheckpointExtras ea, eb;
  const SolverState x = read_checkpoint(a, ea), y = read_checkpoint(b, eb);
  return x.dim == y.dim && x.step == y.step && x.next_id == y.next_id &&
         x.history_slots == y.history_slots && same_bits(x.position, y.position) &&
         same_bits(x.velocity, y.velocity) && same_bits(x.force, y.force) &&
         same_bits(x.angular_velocity, y.angular_velocity) && same_bits(x.torque, y.torque) &&
         x.species == y.species && x.id == y.id && x.history_partner == y.history_partner &&
         same_bits(x.history_spring, y.history_spring) &&
         same_bits(x.history_obstacle_spring, y.history_obstacle_spring) &&
         same_bits(x.reference_position, y.reference_position) &&
         x.neighbour_offsets == y.neighbour_offsets && x.neighbours == y.neighbours &&
         x.list_builds == y.list_builds && x.removed_low == y.removed_low &&
         x.removed_high == y.removed_high && ea.rng_counter == eb.rng_counter &&
         ea.inserted == eb.inserted && ea.deleted_outlet == eb.deleted_outlet &&
         ea.deleted_inlet == eb.deleted_inlet &&
         std::memcmp(&ea.insertion_carry, &eb.insertion_carry, sizeof(double)) == 0 &&
         same_sums(ea.bin_sums, eb.bin_sums) && ea.bin_shape == eb.bin_shape &&
         ea.scene_resolved == eb.scene_resolved;
}

}  // namespace granshock::testing

// Field sampling of a bow-shock run (docs/fields.md, "Sampling"): where the bins are
// (a grid over the domain aligned with the obstacle and, with an obstacle, the fine
// stagnation-line profile),
// when samples are taken (every output.sample_every steps of the production window) and
// which block of the window each sample adds to.
#pragma once

#include <vector>

#include "core/bin_layout.hpp"
#include "core/scene.hpp"

namespace granshock {

class SamplingPlan {
 public:
  // The stagnation-line profile: columns of 0.5 d across 6 d centred on the axis, rows of
  // about 0.5 d (in particle diameters).
  static constexpr int kProfileColumns = 12;
  static constexpr double kProfileColumnWidth = 0.5, kProfileRowHeight = 0.5;

  explicit SamplingPlan(const Scene& scene);

  const FieldSampling& layout() const { return layout_; }
  int blocks() const { return layout_.grid.blocks; }
  long first_step() const { return first_step_; }
  bool due(long step) const;
  long next_after(long step) const;  // the next sampled step after `step`
  int block_of(long step) const;     // the block a sample at `step` adds to
  // Samples per block taken by the end of `step` (what a checkpoint there must hold).
  std::vector<long> samples_by(long step) const;

 private:
  FieldSampling layout_;
  long first_step_ = 0, total_steps_ = 0, every_ = 1;
};

}  // namespace granshock

#include "sampling_plan.hpp"

#include <algorithm>
#include <cmath>

namespace granshock {

// Square bins over the whole domain and, with an obstacle, a strip 4 d wide on its axis
// cut into 0.5 d bins from the inlet to the obstacle's surface (the stagnation-line
// profile that resolves the detachment length better than 3 d bins).
SamplingPlan::SamplingPlan(const Scene& s)
    : first_step_(long(std::llround(s.run.production_start_s / s.setup.dt))),
      total_steps_(s.total_steps()),
      every_(s.run.sample_every) {
  BinLayout& g = layout_.grid;
  g.n_species = int(s.setup.species.size());
  g.bin_size = s.bin_size_m;
  g.nx = std::max(1, int(s.setup.box.length(0) / g.bin_size + 1e-9));
  g.ny = std::max(1, int(s.setup.box.length(1) / g.bin_size + 1e-9));
  g.x0 = s.setup.box.lo[0];
  g.y0 = s.setup.box.lo[1];
  g.blocks = s.run.blocks;
  layout_.strategy = s.field_scatter;
  if (s.setup.obstacle) {
    const Obstacle& c = *s.setup.obstacle;
    ProfileLayout& p = layout_.profile;
    p.x_lo = c.centre[0] - 2 * s.d_m;
    p.x_hi = c.centre[0] + 2 * s.d_m;
    p.y0 = s.setup.box.lo[1];
    p.dy = 0.5 * s.d_m;
    p.n = std::max(1, int((c.centre[1] - c.radius_m() - p.y0) / p.dy));
  }
}

bool SamplingPlan::due(long step) const {
  return step >= first_step_ && step < total_steps_ && (step - first_step_) % every_ == 0;
}

long SamplingPlan::next_after(long step) const {
  if (step < first_step_) return first_step_;
  return first_step_ + ((step - first_step_) / every_ + 1) * every_;
}

int SamplingPlan::block_of(long step) const {
  const long span = total_steps_ - first_step_;
  return int(std::min<long>(blocks() - 1, (step - first_step_) * blocks() / span));
}

std::vector<long> SamplingPlan::samples_by(long step) const {
  std::vector<long> samples(std::size_t(blocks()), 0);
  for (long s = first_step_; s <= step && s < total_steps_; s += every_)
    ++samples[std::size_t(block_of(s))];
  return samples;
}

}  // namespace granshock

#include "cases/bow_shock/sampling_plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "models/obstacle_shapes.hpp"
#include "models/sampled_layer.hpp"

namespace granshock {

namespace {

// The number of whole bins of about `size` that tile `length` (at least one).
int bins_tiling(double length, double size) {
  return std::max(1, int(std::lround(length / size)));
}

// Rows of about `size` from the inlet with a row edge on the obstacle's upstream face
// (all rows the same height); `count` rows reach from the inlet to `end`.
struct Rows {
  double height = 0;
  int count = 0;
};
Rows rows_to_face(double y_lo, double face, double end, double size) {
  Rows r;
  if (!(face > y_lo)) {
    r.height = (end - y_lo) / bins_tiling(end - y_lo, size);
  } else {
    r.height = (face - y_lo) / bins_tiling(face - y_lo, size);
  }
  r.count = std::max(1, int(std::ceil((end - y_lo) / r.height - 1e-9)));
  return r;
}

}  // namespace

// The grid and the stagnation-line profile (docs/fields.md, section 1: "Where the bins
// are"). Grid: columns of W/nx tile the periodic width, one of them centred on the
// obstacle's axis (the column that wraps across the periodic boundary holds both of its
// ends); rows of equal height put a row edge on the obstacle's upstream face y_c - R and
// run to the outlet, the last one clipped there. Profile: 12 columns of 0.5 d on the axis
// (strips of 1 to 6 d are sums of them) cut into rows of about 0.5 d from the inlet to the
// face, so that coarser rows merged from the face upstream keep the edge on the face.
SamplingPlan::SamplingPlan(const Scene& s)
    : first_step_(long(std::llround(s.run.production_start_s / s.setup.dt))),
      total_steps_(s.total_steps()),
      every_(s.run.sample_every) {
  const Box& box = s.setup.box;
  const Obstacle* obstacle = s.setup.obstacle ? &*s.setup.obstacle : nullptr;
  BinLayout& g = layout_.grid;
  g.n_species = int(s.setup.species.size());
  g.blocks = s.run.blocks;
  g.dim = s.setup.dim;  // 3-D: columns through the layer (docs/fields.md, "Three dimensions")
  const std::array<double, 2> layer = sampled_z_range(s);
  g.z0 = layer[0];
  g.depth = layer[1];
  g.nx = bins_tiling(box.length(0), s.bin_size_m);
  g.dx = box.length(0) / g.nx;
  g.x0 = box.lo[0];
  if (box.periodic[0] && obstacle) {
    g.x_period = box.length(0);
    const double first_edge = obstacle->centre[0] - 0.5 * g.dx - box.lo[0];
    double offset = first_edge - std::floor(first_edge / g.dx) * g.dx;
    if (offset > g.dx * (1 - 1e-9)) offset = 0;  // an edge on lo, up to round-off
    g.x0 = box.lo[0] + offset;
  }
  const double face = obstacle ? obstacle_upstream_face(*obstacle) : box.lo[1];
  const Rows rows = rows_to_face(box.lo[1], face, box.hi[1], s.bin_size_m);
  g.y0 = box.lo[1];
  g.dy = rows.height;
  g.ny = rows.count;
  layout_.strategy = s.field_scatter;
  if (obstacle && face > box.lo[1]) {
    BinLayout& p = layout_.profile;
    p.n_species = g.n_species;
    p.blocks = g.blocks;
    p.dim = g.dim;
    p.depth = g.depth;
    p.z0 = g.z0;
    p.nx = kProfileColumns;
    p.dx = kProfileColumnWidth * s.d_m;
    p.x0 = obstacle->centre[0] - 0.5 * p.nx * p.dx;
    const Rows profile_rows = rows_to_face(box.lo[1], face, face, kProfileRowHeight * s.d_m);
    p.y0 = box.lo[1];
    p.dy = profile_rows.height;
    p.ny = profile_rows.count;
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

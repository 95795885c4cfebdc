#include "cases/bow_shock/inflow.hpp"

#include "models/obstacle_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace granshock {

InflowController::InflowController(const Scene& scene) : scene_(scene) {
  const InflowSpec& in = scene.inflow;
  period_steps_ = std::max(1L, long(std::llround(in.strip_m / in.speed_m_per_s / scene.setup.dt)));
  // The strip length actually swept between batches (the period is a whole number of
  // steps), so the rate n_inf U W is met exactly.
  const double swept = period_steps_ * scene.setup.dt * in.speed_m_per_s;
  // (phi W swept) depth / measure: in 2-D the product the rate always was, bit for bit.
  per_batch_ = in.area_fraction * scene.setup.box.length(0) * swept * scene.depth() /
               scene.mean_particle_measure();
}

double InflowController::requested() const {
  const std::uint64_t batches = events_ > prefill_events_ ? events_ - prefill_events_ : 0;
  return prefill_requested_ + double(batches) * per_batch_;
}

bool InflowController::falls_short() const {
  const double missing = shortfall();
  return missing > 2.0 && missing > kShortfallWarning * requested();
}

int InflowController::insert_batch(SolverStepping& solver, double y_lo, double y_hi,
                                   double expected, bool rebuild_lists) {
  const double wanted = expected + carry_;
  InsertionRequest rq;
  rq.x_range = {scene_.setup.box.lo[0], scene_.setup.box.hi[0]};
  rq.y_range = {y_lo, y_hi};
  if (scene_.setup.dim == 3) {
    // Centres across the whole layer: a radius clear of a slab's walls.
    const Box& box = scene_.setup.box;
    const double margin = scene_.setup.z_walls ? 0.5 * scene_.setup.max_diameter() : 0;
    rq.z_range = {box.lo[2] + margin, box.hi[2] - margin};
  }
  rq.count = int(std::floor(wanted));
  rq.number_fraction = scene_.inflow.number_fraction;
  rq.mean_velocity = {0, scene_.inflow.speed_m_per_s};
  rq.sigma_m_per_s = scene_.inflow.sigma;
  rq.seed = scene_.run.seed;
  rq.event = events_++;
  rq.inserted_before = inserted_;
  rq.rebuild_lists = rebuild_lists;
  const int placed = solver.insert(rq);
  inserted_ += placed;
  carry_ = std::min(wanted - placed, per_batch_);
  return placed;
}

double InflowController::free_area(double y_lo, double y_hi) const {
  const double slab = scene_.setup.box.length(0) * (y_hi - y_lo);
  const auto& obstacle = scene_.setup.obstacle;
  return obstacle
             ? slab - obstacle_kept_out_area(*obstacle, scene_.setup.max_diameter(), y_lo, y_hi)
             : slab;
}

template <class F>
void InflowController::for_each_prefill_slab(F&& f) const {
  const double strip = scene_.inflow.strip_m;
  const double length = scene_.setup.box.length(1);
  const double per_area = per_batch_ / (period_steps_ * scene_.setup.dt *
                                        scene_.inflow.speed_m_per_s * scene_.setup.box.length(0));
  for (double y = strip; y < length; y += strip) {
    const double top = std::min(y + strip, length);
    f(y, top, per_area * free_area(y, top));
  }
}

void InflowController::count_prefill() {
  prefill_requested_ = 0;
  prefill_events_ = 0;
  for_each_prefill_slab([&](double, double, double expected) {
    prefill_requested_ += expected;
    ++prefill_events_;
  });
}

void InflowController::prefill(SolverStepping& solver,
                               const std::function<void(long done, long slabs)>& progress) {
  count_prefill();
  long done = 0;
  for_each_prefill_slab([&](double y, double top, double expected) {
    insert_batch(solver, y, top, expected, false);
    if (progress) progress(++done, long(prefill_events_));
  });
  // Lists are rebuilt once, after the last slab (insertion itself needs only positions),
  // also when that slab placed nothing.
  solver.rebuild_lists();
  carry_ = 0;
}

std::uint64_t InflowController::events_by(long step) const {
  std::uint64_t prefill = 0;
  for_each_prefill_slab([&](double, double, double) { ++prefill; });
  // insert_if_due draws one batch at step 0 and every period after.
  return prefill + std::uint64_t(step / period_steps_) + 1;
}

void InflowController::insert_if_due(SolverStepping& solver, long step) {
  if (step % period_steps_ != 0) return;
  insert_batch(solver, 0.0, scene_.inflow.strip_m, per_batch_);
}

void InflowController::restore(std::uint64_t events, long inserted, double carry) {
  count_prefill();
  events_ = events;
  inserted_ = inserted;
  carry_ = carry;
}

}  // namespace granshock

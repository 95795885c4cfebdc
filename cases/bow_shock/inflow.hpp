// The inflow of a bow-shock scene (docs/design.md, "The bow-shock scene"): particles enter through
// the strip y in [0, strip] at the upstream state (phi_inf, U, sigma, number fractions).
//
// Every strip/U seconds a batch of n_inf W strip particles is placed uniformly in the
// strip: the batch before has moved one strip length downstream by then, so the batches
// tile the flow and the density downstream of the strip is n_inf (the strip itself holds
// the batch that is just entering). The fractional remainder, and any particle that
// found no room, is carried to the next batch, so the mean rate is exact while there is
// room. The carry is capped at one batch: a strip that stays full (a shock reaching the
// inlet) must not make every later request larger without end. What could not be placed
// is counted (requested, inserted, backlog, lost) and reported by the run.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/scene.hpp"
#include "core/solver_stepping.hpp"

namespace granshock {

class InflowController {
 public:
  explicit InflowController(const Scene& scene);

  long period_steps() const { return period_steps_; }
  double particles_per_batch() const { return per_batch_; }

  // Fills the domain downstream of the strip with the upstream state, batch by batch,
  // so the flow starts developed instead of waiting one transit time. `progress`, when
  // given, is called after each batch with the slabs filled and their number, on every
  // process (a prefill of 3e7 particles takes minutes: a run reports progress and checks
  // for signals there).
  void prefill(SolverStepping& solver,
               const std::function<void(long done, long slabs)>& progress = {});
  // Inserts a batch when `step` is an insertion step.
  void insert_if_due(SolverStepping& solver, long step);

  // Particles the prefill and every inflow batch so far asked for (a pure function of
  // the scene and events(), so resumed runs need not store it), and the shortfall.
  double requested() const;
  double shortfall() const { return requested() - double(inserted_); }  // backlog + lost
  double backlog() const { return carry_; }
  // True once the inflow falls more than kShortfallWarning short of what it requested.
  bool falls_short() const;
  static constexpr double kShortfallWarning = 0.03;
  // Batches drawn by the end of `step` (the prefill's included): the RNG events a
  // checkpoint at that step must have used.
  std::uint64_t events_by(long step) const;

  // State carried by checkpoints.
  std::uint64_t events() const { return events_; }
  long inserted() const { return inserted_; }
  double carry() const { return carry_; }
  void restore(std::uint64_t events, long inserted, double carry);

 private:
  int insert_batch(SolverStepping& solver, double y_lo, double y_hi, double expected,
                   bool rebuild_lists = true);
  // Area of the slab y in [y_lo, y_hi] where insertion may place particles: the slab
  // minus the disk around the obstacle that insertion keeps clear.
  double free_area(double y_lo, double y_hi) const;
  // Calls f(y_lo, y_hi, expected particles) for each slab the prefill fills, in order.
  template <class F>
  void for_each_prefill_slab(F&& f) const;
  void count_prefill();  // by prefill() and restore(), once the scene passed its checks

  const Scene& scene_;
  long period_steps_ = 1;
  double per_batch_ = 0;  // expected particles per batch
  double prefill_requested_ = 0;
  std::uint64_t prefill_events_ = 0;
  std::uint64_t events_ = 0;  // batches drawn so far: the RNG stream of the next one
  long inserted_ = 0;
  double carry_ = 0;
};

}  // namespace granshock

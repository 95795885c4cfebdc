// Many fused steps in one parallel region, for host backends (docs/design.md, "The
// solver"). One region per step costs a fork, a join and the host's turn between them,
// more when the host deschedules a thread: a tenth of a small scene's step (measured in
// docs/benchmarks.md, "Design choices, measured"). Here one team of all threads runs the fused pass
// (fused_step.hpp) step after step; the team's reduction of each step's top speed is the
// barrier between steps, and every thread advances the same copy of the speed bound
// (neighbours/rebuild_watch.hpp) with it, so all decide alike to go on: while the next
// drift may be reported by speed, exactly when the host's loop would take another fused
// step without an exact check. The host then replays the reported speeds into its watch.
// The arithmetic per particle is that of the one-step pass, so the trajectory is bitwise
// the same (tests/unit/test_backend_agreement.cpp, `FusedSteps`). Each thread's share of
// the runs is cut by the measured time of the earlier regions (thread_shares.hpp), and
// the pass times every share for the next cut, in every timed_every-th step: a clock read
// costs 53 ns on the developers' VM (kvm-clock), and more where the clock is not read in
// user space.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/host_clock.hpp"
#include "kernels/neighbours/rebuild_watch.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/solver/fused_step.hpp"

namespace granshock {

// Regions of many steps pay where a step is short; where the host team's reduction costs
// more than the region it saves they do not (docs/benchmarks.md, "Many steps per region").
// Above this many particles per thread the solver keeps one region per step.
constexpr int step_regions_particles_per_thread = 8192;

template <class V, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
struct FusedStepsPass {
  using Real = typename VariantTypes<V, ExecSpace>::Real;
  using Mem = typename VariantTypes<V, ExecSpace>::Mem;
  using Kernel = FusedStepKernel<V, ExecSpace, Paths>;
  using Member = typename Kokkos::TeamPolicy<ExecSpace>::member_type;

  // The pass that reads the current buffers and writes the second ones, and the pass back.
  Kernel forth, back;
  SpeedBound bound;  // the host watch's, before the first step (reported by speed)
  long max_steps;
  Kokkos::View<double*, Mem> top_speed2;  // of each step done
  Kokkos::View<long, Mem> done;
  Kokkos::View<const int*, Mem> cuts;        // thread t's runs: [cuts(t), cuts(t + 1))
  Kokkos::View<double*, Mem> share_seconds;  // each share's time over the region

  static constexpr long timed_every = 4;

  KOKKOS_INLINE_FUNCTION void operator()(const Member& team) const {
    SpeedBound b = bound;
    long k = 0;
    double seconds = 0;  // this thread's share, the timed steps
    int mine = -1;       // which share that is
    while (k < max_steps) {
      const Kernel& kernel = k % 2 == 0 ? forth : back;
      Real top = 0;
      // One contiguous share of the runs per thread, as a static range policy gives: the
      // host team's TeamThreadRange deals items out in turn, and every run's neighbours
      // would then be in the other core's cache.
      Kokkos::parallel_reduce(
          Kokkos::TeamThreadRange(team, team.team_size()),
          [&](const int share, Real& worst) {
            const bool timed = k % timed_every == 0;
            const std::int64_t start = timed ? host_nanoseconds() : 0;
            for (int run = cuts(share), end = cuts(share + 1); run < end; ++run) kernel(run, worst);
            if (timed) seconds += 1e-9 * double(host_nanoseconds() - start);
            mine = share;
          },
          Kokkos::Max<Real>(top));
      if (team.team_rank() == 0) top_speed2(k) = double(top);
      b.drifted(double(top));
      ++k;
      if (!b.next_drift_by_speed()) break;
    }
    if (mine >= 0) share_seconds(mine) = seconds;
    if (team.team_rank() == 0) done() = k;
  }
};

}  // namespace granshock

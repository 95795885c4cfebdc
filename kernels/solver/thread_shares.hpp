// The threads' shares of the multi-step fused pass (fused_steps.hpp): contiguous runs of
// work items, cut so that each thread's share takes the same measured time
// (core/work_shares.hpp). Each region times every thread's share of every fourth step
// (FusedStepsPass::timed_every); after a
// region of enough steps the cuts move half of the way to the balanced ones, when the
// slowest share took more than `tolerated_imbalance` times the mean. Where the work per
// particle differs (the bow shock against the free stream and the wake) equal shares
// leave one thread waiting at every step's barrier (docs/benchmarks.md, "Threads on a
// small scene"). The cuts never change a particle's arithmetic: the results are the same
// bit for bit whatever they are (tests/unit/test_backend_agreement.cpp, `ThreadShares`).
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <vector>

#include "core/run_modes.hpp"
#include "core/solver_statistics.hpp"
#include "core/work_shares.hpp"

namespace granshock {

template <class Mem>
class ThreadShares {
 public:
  using Mode = ThreadShareMode;
  explicit ThreadShares(Mode mode = Mode::by_time) : mode_(mode) {}

  static constexpr double tolerated_imbalance = 1.03;
  static constexpr long least_steps = 8;  // fewer (2 timed): too little to move the cuts
  static constexpr double step = 0.5;

  // The cuts for `items` work items among `threads` (kept from the last region, scaled
  // when the count changed), in a host-readable View the pass reads.
  Kokkos::View<int*, Mem> cuts(int items, int threads) {
    if (int(cuts_.size()) != threads + 1 || mode_ == Mode::equal) {
      cuts_ = equal_cuts(items, threads);
    } else if (cuts_.back() != items) {
      cuts_ = rescaled_cuts(cuts_, items);
    }
    if (mode_ == Mode::alternating && threads > 1) {
      const int quarter = ++moves_ % 2 == 1 ? 1 : 3;
      cuts_ = equal_cuts(items, threads);
      cuts_[1] = int(long(items) * quarter / 4);
      for (int k = 2; k < threads; ++k)
        cuts_[std::size_t(k)] = std::max(cuts_[1], cuts_[std::size_t(k)]);
    }
    if (int(view_.extent(0)) != threads + 1) {
      view_ = Kokkos::View<int*, Mem>("thread_share_cuts", threads + 1);
      seconds_ = Kokkos::View<double*, Mem>("thread_share_seconds", threads);
    }
    for (int k = 0; k <= threads; ++k) view_(k) = cuts_[std::size_t(k)];
    return view_;
  }
  // Where the pass writes each share's seconds.
  const Kokkos::View<double*, Mem>& seconds() const { return seconds_; }

  // After a region of `steps` steps with the cuts of the last cuts() call.
  void balance(long steps) {
    if (mode_ != Mode::by_time || steps < least_steps) return;
    std::vector<double> took(seconds_.extent(0));
    for (std::size_t t = 0; t < took.size(); ++t) took[t] = seconds_(t);
    last_imbalance_ = share_imbalance(took);
    if (last_imbalance_ <= tolerated_imbalance) return;
    const std::vector<int> next = balanced_cuts(cuts_, took, step);
    if (next != cuts_) ++moves_;
    cuts_ = next;
  }

  const std::vector<int>& current() const { return cuts_; }
  ThreadShareStats stats() const {
    ThreadShareStats s{{}, moves_, last_imbalance_};
    if (cuts_.size() > 1 && cuts_.back() > 0)
      for (std::size_t t = 0; t + 1 < cuts_.size(); ++t)
        s.shares.push_back(double(cuts_[t + 1] - cuts_[t]) / double(cuts_.back()));
    return s;
  }

 private:
  Mode mode_;
  std::vector<int> cuts_;
  Kokkos::View<int*, Mem> view_;
  Kokkos::View<double*, Mem> seconds_;
  long moves_ = 0;
  double last_imbalance_ = 1;
};

}  // namespace granshock

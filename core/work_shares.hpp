// Contiguous shares of a range of work items cut so that each takes the same measured
// time: the threads' shares of the multi-step fused pass (kernels/solver/fused_steps.hpp,
// kernels/solver/thread_shares.hpp). Equal shares of particles are unequal in work where
// a scene is not uniform: the bow shock is dense, the obstacle's wake nearly empty
// (docs/benchmarks.md, "Threads on a small scene"). The cuts change which thread moves a
// particle, never how, so the results do not depend on them.
#pragma once

#include <vector>

namespace granshock {

// cuts[0] = 0 <= cuts[1] <= ... <= cuts[T] = items: share t is [cuts[t], cuts[t + 1]).
std::vector<int> equal_cuts(int items, int shares);

// The cuts that give every share the same time, were the time per item constant within
// each of the old shares (share t took seconds[t]), each moved `step` of the way there
// from the old cut (1: all the way; less damps the measurements' noise). An empty old
// share is taken to cost nothing. Without any time measured the cuts stay.
std::vector<int> balanced_cuts(const std::vector<int>& cuts, const std::vector<double>& seconds,
                               double step);

// The longest share's time over the mean: 1 when balanced.
double share_imbalance(const std::vector<double>& seconds);

// The cuts of one range carried to a range of `items` items (a count that grew or
// shrank): scaled, so that a cut stays at the same fraction of the range.
std::vector<int> rescaled_cuts(const std::vector<int>& cuts, int items);

}  // namespace granshock

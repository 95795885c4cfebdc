#include "core/work_shares.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace granshock {

std::vector<int> equal_cuts(int items, int shares) {
  std::vector<int> cuts(std::size_t(shares) + 1);
  for (int t = 0; t <= shares; ++t) cuts[std::size_t(t)] = int(long(items) * t / shares);
  return cuts;
}

std::vector<int> balanced_cuts(const std::vector<int>& cuts, const std::vector<double>& seconds,
                               double step) {
  const std::size_t shares = seconds.size();
  const double total = std::accumulate(seconds.begin(), seconds.end(), 0.0);
  if (!(total > 0) || cuts.size() != shares + 1) return cuts;
  // The cumulative time, piecewise linear in the item index: at cuts[t] it is the sum of
  // the shares before t. New cut k lies where it reaches k/T of the total.
  std::vector<int> next = cuts;
  std::size_t t = 0;
  double before = 0;  // time of the shares before t
  for (std::size_t k = 1; k < shares; ++k) {
    const double target = total * double(k) / double(shares);
    while (t + 1 < shares && before + seconds[t] < target) before += seconds[t++];
    const double width = double(cuts[t + 1] - cuts[t]);
    const double within = seconds[t] > 0 ? (target - before) / seconds[t] : 0;
    const double balanced = double(cuts[t]) + std::clamp(within, 0.0, 1.0) * width;
    next[k] = int(std::lround(double(cuts[k]) + step * (balanced - double(cuts[k]))));
  }
  for (std::size_t k = 1; k < shares; ++k) next[k] = std::clamp(next[k], next[k - 1], next.back());
  return next;
}

double share_imbalance(const std::vector<double>& seconds) {
  if (seconds.empty()) return 1;
  const double total = std::accumulate(seconds.begin(), seconds.end(), 0.0);
  if (!(total > 0)) return 1;
  return *std::max_element(seconds.begin(), seconds.end()) * double(seconds.size()) / total;
}

std::vector<int> rescaled_cuts(const std::vector<int>& cuts, int items) {
  std::vector<int> scaled = cuts;
  const long old_items = cuts.back();
  for (std::size_t k = 0; k < cuts.size(); ++k)
    scaled[k] = old_items > 0 ? int(long(cuts[k]) * items / old_items)
                              : int(long(items) * long(k) / long(cuts.size() - 1));
  scaled.front() = 0;
  scaled.back() = items;
  return scaled;
}

}  // namespace granshock

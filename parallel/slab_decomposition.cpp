#include "parallel/slab_decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/user_error.hpp"

namespace granshock {

namespace {

void check(int ranks, int axis, int rows, int min_rows, bool periodic) {
  if (ranks < 1) throw std::invalid_argument("a decomposition needs at least one rank");
  if (axis != 0 && axis != 1) throw std::invalid_argument("slabs along x (0) or y (1)");
  if (long(ranks) * min_rows <= rows) return;
  const char* name = axis == 0 ? "x" : "y";
  throw UserError(fmt::format(
      "{} MPI processes with slabs along {} need {} cell {} (at least {} per slab{}), and the "
      "box has {}: run on at most {} processes, or slab the other axis",
      ranks, name, long(ranks) * min_rows, axis == 0 ? "columns" : "rows", min_rows,
      periodic && min_rows > 1 ? fmt::format(", {} being periodic", name) : "", rows,
      rows / std::max(min_rows, 1)));
}

}  // namespace

SlabDecomposition::SlabDecomposition(int axis, double lo, double length, std::vector<int> first_row,
                                     int min_rows, bool periodic)
    : axis_(axis),
      lo_(lo),
      length_(length),
      inv_row_width_(first_row.back() / length),
      first_row_(std::move(first_row)),
      min_rows_(min_rows),
      periodic_(periodic) {}

SlabDecomposition SlabDecomposition::equal(int ranks, int axis, double lo, double length, int rows,
                                           int min_rows, bool periodic) {
  check(ranks, axis, rows, min_rows, periodic);
  std::vector<int> first(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) first[r + 1] = first[r] + rows / ranks + (r < rows % ranks);
  return {axis, lo, length, first, min_rows, periodic};
}

SlabDecomposition SlabDecomposition::balanced(int ranks, int axis, double lo, double length,
                                              const std::vector<long>& count_per_row, int min_rows,
                                              bool periodic) {
  const int rows = int(count_per_row.size());
  check(ranks, axis, rows, min_rows, periodic);
  std::vector<long> before(rows + 1, 0);  // particles in rows [0, k)
  std::partial_sum(count_per_row.begin(), count_per_row.end(), before.begin() + 1);
  const long total = before.back();
  std::vector<int> first(ranks + 1, 0);
  first[ranks] = rows;
  for (int k = 1; k < ranks; ++k) {
    // Integer target k * total / ranks, compared exactly: no rounding decides a cut.
    const auto distance = [&](int b) { return std::abs(before[b] * ranks - long(k) * total); };
    const int lowest = first[k - 1] + min_rows;
    const int highest = rows - (ranks - k) * min_rows;
    int best = lowest;
    for (int b = lowest + 1; b <= highest; ++b)
      if (distance(b) < distance(best)) best = b;
    first[k] = best;
  }
  return {axis, lo, length, first, min_rows, periodic};
}

long SlabDecomposition::heaviest(const std::vector<long>& count_per_row) const {
  long most = 0;
  for (int r = 0; r < ranks(); ++r)
    most = std::max(most, std::accumulate(count_per_row.begin() + first_row_[r],
                                          count_per_row.begin() + first_row_[r + 1], 0L));
  return most;
}

long SlabDecomposition::row_of(double coordinate) const {
  return long(std::floor((coordinate - lo_) * inv_row_width_));
}

int SlabDecomposition::owner(double coordinate) const {
  return owner_of_row(int(std::clamp<long>(row_of(coordinate), 0, rows() - 1)));
}

int SlabDecomposition::owner_of_row(int row) const {
  // The last slab whose first row is at or before `row`.
  const auto it = std::upper_bound(first_row_.begin(), first_row_.end() - 1, row);
  return int(it - first_row_.begin()) - 1;
}

std::vector<int> SlabDecomposition::neighbours(int rank) const {
  std::vector<int> out;
  const int n = ranks();
  for (const int step : {-1, 1}) {
    int other = rank + step;
    if (periodic_) other = (other + n) % n;
    if (other < 0 || other >= n || other == rank) continue;
    if (std::find(out.begin(), out.end(), other) == out.end()) out.push_back(other);
  }
  return out;
}

}  // namespace granshock

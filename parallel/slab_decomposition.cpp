#include "slab_decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "user_error.hpp"

namespace granshock {

namespace {

void check(int ranks, int rows, int min_rows) {
  if (ranks < 1) throw std::invalid_argument("a decomposition needs at least one rank");
  if (long(ranks) * min_rows > rows)
    throw UserError(fmt::format(
        "{} MPI processes need {} cell rows of slabs at least {} rows wide each, and the box "
        "has {}: run on at most {} processes",
        ranks, long(ranks) * min_rows, min_rows, rows, rows / std::max(min_rows, 1)));
}

}  // namespace

SlabDecomposition::SlabDecomposition(double lo, double length, std::vector<int> first_row,
                                     int min_rows, bool periodic)
    : lo_(lo),
      length_(length),
      inv_row_width_(first_row.back() / length),
      first_row_(std::move(first_row)),
      min_rows_(min_rows),
      periodic_(periodic) {}

SlabDecomposition SlabDecomposition::equal(int ranks, double lo, double length, int rows,
                                           int min_rows, bool periodic) {
  check(ranks, rows, min_rows);
  std::vector<int> first(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) first[r + 1] = first[r] + rows / ranks + (r < rows % ranks);
  return {lo, length, first, min_rows, periodic};
}

SlabDecomposition SlabDecomposition::balanced(int ranks, double lo, double length,
                                              const std::vector<long>& count_per_row, int min_rows,
                                              bool periodic) {
  const int rows = int(count_per_row.size());
  check(ranks, rows, min_rows);
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
  return {lo, length, first, min_rows, periodic};
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

// The statistical error of a quantity from block averages (docs/fields.md, section 6): the
// standard error of the mean of B block values, s_B / sqrt(B), with s_B their sample
// standard deviation. It assumes the blocks are independent.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

namespace granshock {

// NaN with fewer than 2 values.
inline double block_standard_error(const std::vector<double>& values) {
  const double nb = static_cast<double>(values.size());
  if (values.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double mean = 0, variance = 0;
  for (double v : values) mean += v / nb;
  for (double v : values) variance += (v - mean) * (v - mean) / (nb - 1);
  return std::sqrt(variance / nb);
}

}  // namespace granshock

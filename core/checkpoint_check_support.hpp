// Message helpers shared by the checkpoint checks (core/checkpoint_checks.hpp).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "core/checkpoint_checks.hpp"

namespace granshock::checks {

[[noreturn]] inline void fail(const std::string& what) {
  throw InvalidCheckpoint(what);
}

// "/state/position[12]": the element a message is about (flat, row-major index).
inline std::string at(const char* dataset, std::size_t index) {
  return fmt::format("{}[{}]", dataset, index);
}

template <class T>
void expect_size(const char* dataset, const std::vector<T>& values, std::size_t expected,
                 const std::string& because) {
  if (values.size() != expected)
    fail(fmt::format("{} has {} values, expected {} ({})", dataset, values.size(), expected,
                     because));
}

inline void expect_finite(const char* dataset, const std::vector<double>& values) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!std::isfinite(values[k]))
      fail(fmt::format("{} = {} is not finite", at(dataset, k), values[k]));
}

inline double largest(const std::vector<double>& values) {
  double top = 0;
  for (double v : values) top = std::max(top, v);
  return top;
}

// The field sums part of check_run (checkpoint_sums_checks.cpp).
void check_field_sums(const CheckpointExtras& e, const RunFit& fit);

}  // namespace granshock::checks

// The field-sampling part of the solver interface (core/solver.hpp; docs/fields.md):
// configure once, then add samples to a block; the sums as host arrays, and their restore.
#pragma once

#include <vector>

#include "core/bin_layout.hpp"

namespace granshock {

class SolverSampling {
 public:
  virtual ~SolverSampling() = default;

  virtual void configure_sampling(const FieldSampling& sampling) = 0;
  virtual void sample_fields(int block) = 0;
  // [blocks][ny][nx][q] (the grid) and [blocks][n][q] (the profile), summed over processes.
  virtual std::vector<double> field_sums(bool profile) const = 0;
  virtual void restore_field_sums(const std::vector<double>& grid,
                                  const std::vector<double>& profile) = 0;
};

}  // namespace granshock

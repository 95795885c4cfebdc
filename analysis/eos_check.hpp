// How well the measured pressure follows the kinetic-theory equation of state behind the
// sound speed (the paper's eqs. 6-8): p_eos = n T F(phi), F = 1 + (Dim - 1)(1 + e) phi g(phi),
// i.e. n T (1 + (1 + e) phi g(phi)) in 2-D. Reported as the mean of the relative deviation
// p / p_eos - 1 over dilute bins (phi < 0.2) and over dense bins (phi >= 0.3).
#pragma once

#include <string>

#include "analysis/bin_fields.hpp"

namespace granshock {

struct EosCut {
  // Only unmasked bins with at least this many particles counted over all samples: the
  // relative noise of a bin's pressure is about 1/sqrt(count), 3 % at 1000.
  double min_particle_samples = 1000;
  double dilute_below = 0.2;
  double dense_from = 0.3;
};

struct EosCheck {
  double dilute_mean = 0, dense_mean = 0;          // mean of p/p_eos - 1 (NaN without bins)
  double dilute_mean_abs = 0, dense_mean_abs = 0;  // mean of |p/p_eos - 1|
  int dilute_bins = 0, dense_bins = 0;
  std::string dilute_reason, dense_reason;  // why a mean is NaN (empty when it is a number)
};

EosCheck check_equation_of_state(const BinFields& fields, const EosCut& cut = {});

}  // namespace granshock

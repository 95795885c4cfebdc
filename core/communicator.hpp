// The communication seam (docs/design.md, "Seams"): every global reduction the solver
// and the run loop make goes through a Communicator, so that domain decomposition over
// MPI plugs in here without touching the kernels. The neighbour-list rebuild decision
// (max), the diagnostics and particle counts (sums), the overflow flags (any) and the
// field sums (sum in place) are global reductions. The single-process implementation is
// the identity. Halo exchange and migration of particles, the seam's device half, live
// beside the particle store (kernels/particles/particle_exchange.hpp).
#pragma once

#include <vector>

namespace granshock {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual double max(double local) const = 0;
  virtual double sum(double local) const = 0;
  virtual long sum(long local) const = 0;
  virtual bool any(bool local) const = 0;
  virtual void sum_in_place(std::vector<double>& values) const = 0;
};

// One process owns everything: every reduction returns its argument.
class SingleProcess final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  double max(double local) const override { return local; }
  double sum(double local) const override { return local; }
  long sum(long local) const override { return local; }
  bool any(bool local) const override { return local; }
  void sum_in_place(std::vector<double>&) const override {}

  static const SingleProcess& instance() {
    static const SingleProcess one;
    return one;
  }
};

}  // namespace granshock

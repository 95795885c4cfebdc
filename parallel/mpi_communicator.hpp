// The Communicator of core/communicator.hpp over MPI (docs/parallel.md): every global
// reduction of the solver and the run loop as an MPI_Allreduce on one communicator. The
// sums of doubles are reduced by MPI in its own order: they are the same on every rank but
// not, to the last bit, the same as one process's sums.
#pragma once

#include <mpi.h>

#include "core/communicator.hpp"

namespace granshock {

class MpiCommunicator final : public Communicator {
 public:
  explicit MpiCommunicator(MPI_Comm comm = MPI_COMM_WORLD);
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  double max(double local) const override;
  double sum(double local) const override;
  long sum(long local) const override;
  bool any(bool local) const override;
  void sum_in_place(std::vector<double>& values) const override;
  NeighbourBytes exchange_with_neighbours(const std::vector<char>& to_lower, int lower,
                                          const std::vector<char>& to_upper, int upper,
                                          ExpectedBytes expected) const override;
  std::vector<char> gather(const std::vector<char>& bytes, int root) const override;
  std::vector<char> all_gather(const std::vector<char>& bytes) const override;
  // For libraries that take the communicator itself (parallel HDF5).
  MPI_Comm native() const { return comm_; }

 private:
  std::vector<char> gather_to(const std::vector<char>& bytes, int root, bool everywhere) const;
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace granshock

// The communication seam (docs/design.md, "Seams"): every global reduction the solver
// and the run loop make goes through a Communicator, so that domain decomposition over
// MPI plugs in here without touching the kernels. The neighbour-list rebuild decision
// (max), the diagnostics and particle counts (sums), the overflow flags (any) and the
// field sums (sum in place) are global reductions. The single-process implementation is
// the identity. Halo exchange and migration of particles, the seam's device half, live
// beside the particle store (kernels/particles/slab_exchange.hpp) and travel through
// send_receive.
#pragma once

#include <cstring>
#include <type_traits>
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
  // Sends `bytes` to rank `dest` and returns what rank `source` sent to this one, in one
  // exchange (the transport of migration and ghosts, docs/parallel.md). kNone as `dest`
  // sends nothing; as `source` it receives nothing (an open face).
  static constexpr int kNone = -1;
  virtual std::vector<char> send_receive(const std::vector<char>& bytes, int dest,
                                         int source) const = 0;
  // Every rank's bytes concatenated in rank order: on `root` only (empty elsewhere), or on
  // every rank (insertion's overlap test, docs/parallel.md).
  virtual std::vector<char> gather(const std::vector<char>& bytes, int root) const = 0;
  virtual std::vector<char> all_gather(const std::vector<char>& bytes) const = 0;
  bool is_root() const { return rank() == 0; }
};

// Every rank's `value` on rank 0, in rank order (empty elsewhere): per-rank reports.
template <class T>
std::vector<T> gather_to_root(const Communicator& comm, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  std::vector<char> bytes(sizeof value);
  std::memcpy(bytes.data(), &value, sizeof value);
  const std::vector<char> all = comm.gather(bytes, 0);
  std::vector<T> out(all.size() / sizeof value);
  std::memcpy(static_cast<void*>(out.data()), all.data(), all.size());
  return out;
}

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
  std::vector<char> send_receive(const std::vector<char>& bytes, int dest,
                                 int source) const override {
    // Rank 0 to itself (a periodic face of a single slab).
    return dest == 0 && source == 0 ? bytes : std::vector<char>();
  }
  std::vector<char> gather(const std::vector<char>& bytes, int) const override { return bytes; }
  std::vector<char> all_gather(const std::vector<char>& bytes) const override { return bytes; }

  static const SingleProcess& instance() {
    static const SingleProcess one;
    return one;
  }
};

}  // namespace granshock

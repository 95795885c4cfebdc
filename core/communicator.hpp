// The communication seam (docs/design.md, "Seams"): every global reduction the solver
// and the run loop make goes through a Communicator, so that domain decomposition over
// MPI plugs in here without touching the kernels. The neighbour-list rebuild decision
// (max), the diagnostics and particle counts (sums), the overflow flags (any) and the
// field sums (sum in place) are global reductions. The single-process implementation is
// the identity. Halo exchange and migration of particles, the seam's device half, live
// beside the particle store (kernels/particles/slab_exchange.hpp) and travel through
// exchange_with_neighbours.
#pragma once

#include <cstring>
#include <type_traits>
#include <vector>

namespace granshock {

// What Communicator::exchange_with_neighbours brings from each side, and what it is told
// to expect (-1: unknown, a size message first).
struct NeighbourBytes {
  std::vector<char> lower, upper;
};
struct ExpectedBytes {
  long from_lower = -1, from_upper = -1;
};

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual double max(double local) const = 0;
  virtual double sum(double local) const = 0;
  virtual long sum(long local) const = 0;
  virtual bool any(bool local) const = 0;
  bool all(bool local) const { return !any(!local); }
  virtual void sum_in_place(std::vector<double>& values) const = 0;
  // The transport of migration, ghosts and halo (docs/parallel.md): sends `to_lower` to
  // rank `lower` and `to_upper` to rank `upper` and receives what each of them sent this
  // way, all four at once (one round trip; lower and upper may be the same rank). kNone
  // as a neighbour: an open face, nothing sent or received. The sizes of what arrives
  // are exchanged first unless the caller knows them (`expected`, in bytes: the halo
  // between rebuilds, whose ghost counts are fixed).
  static constexpr int kNone = -1;
  virtual NeighbourBytes exchange_with_neighbours(const std::vector<char>& to_lower, int lower,
                                                  const std::vector<char>& to_upper, int upper,
                                                  ExpectedBytes expected = {}) const = 0;
  // Every rank's bytes concatenated in rank order: on `root` only (empty elsewhere), or on
  // every rank (insertion's overlap test, docs/parallel.md).
  virtual std::vector<char> gather(const std::vector<char>& bytes, int root) const = 0;
  virtual std::vector<char> all_gather(const std::vector<char>& bytes) const = 0;
  bool is_root() const { return rank() == 0; }
};

// Every rank's `values` on rank 0, concatenated in rank order (empty elsewhere).
template <class T>
std::vector<T> gather_to_root(const Communicator& comm, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  const char* bytes = reinterpret_cast<const char*>(values.data());
  const std::vector<char> all = comm.gather({bytes, bytes + values.size() * sizeof(T)}, 0);
  std::vector<T> out(all.size() / sizeof(T));
  if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), all.data(), all.size());
  return out;
}
// Every rank's `values` on every rank, concatenated in rank order.
template <class T>
std::vector<T> gather_to_all(const Communicator& comm, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  const char* bytes = reinterpret_cast<const char*>(values.data());
  const std::vector<char> all = comm.all_gather({bytes, bytes + values.size() * sizeof(T)});
  std::vector<T> out(all.size() / sizeof(T));
  if (!out.empty()) std::memcpy(static_cast<void*>(out.data()), all.data(), all.size());
  return out;
}
// Every rank's `value` on rank 0, in rank order (empty elsewhere): per-rank reports.
template <class T>
std::vector<T> gather_to_root(const Communicator& comm, T value) {
  return gather_to_root(comm, std::vector<T>{value});
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
  // Rank 0 with itself as neighbour (a periodic face of a single slab): what it sends up
  // arrives from below, and what it sends down arrives from above.
  NeighbourBytes exchange_with_neighbours(const std::vector<char>& to_lower, int lower,
                                          const std::vector<char>& to_upper, int upper,
                                          ExpectedBytes) const override {
    NeighbourBytes in;
    if (lower == 0 && upper == 0) in = {to_upper, to_lower};
    return in;
  }
  std::vector<char> gather(const std::vector<char>& bytes, int) const override { return bytes; }
  std::vector<char> all_gather(const std::vector<char>& bytes) const override { return bytes; }

  static const SingleProcess& instance() {
    static const SingleProcess one;
    return one;
  }
};

}  // namespace granshock

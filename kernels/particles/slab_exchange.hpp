// Domain decomposition in slabs of cell rows along x or y (docs/parallel.md): the exchange
// half of the communication seam for several processes (communicator.hpp moves the
// bytes; population.hpp inserts and deletes across ranks). A "row" here is a layer of cells along
// the slab axis: a row of the grid for slabs along y, a column for slabs along x. At each list
// rebuild, particles whose row belongs to another slab migrate to it, and each slab sends its
// lowest and highest rows to the slabs below and above as ghosts, appended after the owned
// particles. A row is at least one interaction range (largest diameter + skin) wide, so the ghosts
// are every partner a Verlet list can hold. Between rebuilds the ghosts' positions, velocities (and
// spins) are refreshed from their owners after every position update.
//
// Bitwise the same as one process: every rank sorts into the global cell grid, owned cells
// and ghost cells are disjoint (slab cuts are row boundaries), and the ghost block is in
// increasing cell order with each cell in its owner's (cell, id) order: the two incoming
// rows are merged cell by cell (for slabs along x they interleave, one cell of each per
// grid row). So a particle's list partners come in the same order as in one process;
// ghosts carry the owner's coordinates, so the minimum image is formed alike.
//
// Transport is through host copies (free on host backends; whole arrays on a GPU, a cost
// to remove when the GPU build uses it) and Communicator::exchange_with_neighbours: both
// directions in one round trip, per rebuild (migration, ghosts) and per step (halo, whose
// sizes are known from the rebuild).
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/communicator.hpp"
#include "core/domain.hpp"
#include "core/solver.hpp"  // HaloStats
#include "kernels/device/backends.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/neighbours/cell_grid.hpp"
#include "parallel/slab_decomposition.hpp"

namespace granshock {

// The byte image of chosen rows of Kokkos Views (host mirrors), one array after another.
namespace row_bytes {

template <class View>
int width(const View& v) {
  if constexpr (View::rank == 1) {
    return 1;
  } else {
    return int(v.extent(1));
  }
}

// Host paths, on host mirrors whose rows are stored one after another (LayoutRight, or one
// value per row): a range of rows is one block of bytes. Device paths: the host mirror of
// a GPU's View (LayoutLeft) is copied value by value.
template <class Paths, class View>
constexpr bool rows_are_contiguous() {
  return Paths::host &&
         (View::rank == 1 || std::is_same_v<typename View::array_layout, Kokkos::LayoutRight>);
}

template <class Paths, class View>
void append(std::vector<char>& out, const View& v, int begin, int end) {
  static_assert(std::is_same_v<typename View::memory_space, Kokkos::HostSpace>,
                "host mirrors only");
  using T = typename View::non_const_value_type;
  const int w = width(v);
  if constexpr (rows_are_contiguous<Paths, View>()) {
    if (end <= begin) return;
    const char* from = reinterpret_cast<const char*>(v.data() + std::size_t(begin) * w);
    out.insert(out.end(), from, from + std::size_t(end - begin) * w * sizeof(T));
  } else {
    for (int i = begin; i < end; ++i)
      for (int c = 0; c < w; ++c) {
        T value;
        if constexpr (View::rank == 1) {
          value = v(i);
        } else {
          value = v(i, c);
        }
        const char* bytes = reinterpret_cast<const char*>(&value);
        out.insert(out.end(), bytes, bytes + sizeof(T));
      }
  }
}

// Reads `count` rows into v starting at row `first`; returns the bytes consumed.
template <class Paths, class View>
std::size_t extract(const View& v, const char* in, int first, int count) {
  static_assert(std::is_same_v<typename View::memory_space, Kokkos::HostSpace>,
                "host mirrors only");
  using T = typename View::non_const_value_type;
  const int w = width(v);
  std::size_t at = 0;
  if constexpr (rows_are_contiguous<Paths, View>()) {
    at = std::size_t(count) * w * sizeof(T);
    if (at > 0) std::memcpy(static_cast<void*>(v.data() + std::size_t(first) * w), in, at);
  } else {
    for (int i = first; i < first + count; ++i)
      for (int c = 0; c < w; ++c) {
        T value;
        std::memcpy(&value, in + at, sizeof(T));
        at += sizeof(T);
        if constexpr (View::rank == 1) {
          v(i) = value;
        } else {
          v(i, c) = value;
        }
      }
  }
  return at;
}

}  // namespace row_bytes

// A run of the ghost block: `count` consecutive particles of one neighbour's message, from
// its `first`-th (from: 0 the lower neighbour's, 1 the upper's).
struct GhostRun {
  int from = 0;
  int first = 0;
  int count = 0;
};

template <int Dim, class Store, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
class SlabExchange {
 public:
  using Mem = typename ExecSpace::memory_space;
  using Grid = CellGrid<Dim, Position>;

  // Any axis of the flat cell index, in 2-D and 3-D: a slab's boundary layer is one range
  // of storage per grid row (or per z-layer) across the slab axis (storage_ranges).
  static_assert(Dim == 2 || Dim == 3);

  // Equal slabs of the grid's rows along `axis`; two rows at least where that axis is
  // periodic, so that the rows below and above a slab are two different rows.
  SlabExchange(const Communicator& comm, const Grid& grid, const Box& box, int axis)
      : comm_(comm),
        grid_(grid),
        slabs_(SlabDecomposition::equal(comm.size(), axis, box.lo[axis], box.length(axis),
                                        grid.ncell[axis], box.periodic[axis] ? 2 : 1,
                                        box.periodic[axis])) {
    const int r = comm.rank(), n = comm.size();
    const bool periodic = box.periodic[axis];
    lower_ = r > 0 ? r - 1 : (periodic ? n - 1 : Communicator::kNone);
    upper_ = r + 1 < n ? r + 1 : (periodic ? 0 : Communicator::kNone);
  }

  const HaloStats& stats() const { return stats_; }
  int axis() const { return slabs_.axis(); }
  // The rank owning a coordinate along the slab axis: by its cell row, as the cell sort
  // computes it.
  int owner_of(Position coordinate) const {
    return slabs_.owner_of_row(grid_.coord(axis(), coordinate));
  }
  bool owns(Position coordinate) const { return owner_of(coordinate) == comm_.rank(); }

  // Collective. Where this rank's particles, sorted by `cells`, go in one process's order
  // (that of the flat cell index): each layer of the index across the slabs holds every
  // rank's cells of it in rank order (core/snapshot_part.hpp). Sets `total` to every
  // rank's count.
  std::vector<FileRows> file_rows(const std::vector<int>& cells, long& total) const {
    const auto [stride, layer] = axis_strides();
    const int rank = comm_.rank();
    std::vector<long> counts(std::size_t(grid_.total() / layer), 0);
    for (const int cell : cells) {
      const int row = (cell / stride) % grid_.ncell[axis()];
      if (row < slabs_.first_row(rank) || row >= slabs_.end_row(rank))
        throw std::logic_error("a particle's reference cell lies outside its process's slab");
      ++counts[std::size_t(cell / layer)];
    }
    const std::vector<long> all = gather_to_all(comm_, counts);
    total = std::accumulate(all.begin(), all.end(), 0L);
    return file_rows_by_layer(all, int(counts.size()), rank);
  }

  // Slab boundaries moved at list rebuilds (docs/parallel.md, "Load balance"): equal
  // slabs of rows throughout, or balanced by particle count, or by measured work (each
  // particle weighs its rank's compute time per particle-step since the last check).
  void set_balance(SlabBalance balance) { balance_ = balance; }
  // The compute time (halo and waits excluded) of `particle_steps` on this rank.
  void account_work(double seconds, double particle_steps) {
    work_seconds_ += seconds;
    work_particle_steps_ += particle_steps;
  }

  // Hands the owned particles whose row is now another slab's to it and appends those
  // that arrived; returns the new owned count. `grow(capacity)` enlarges the store.
  // Between rebuilds a particle moves less than a row, so one exchange with the adjacent
  // slabs does; after a rebalance one may be several slabs away, and passes repeat
  // (forwarding through the slabs between) until every particle is home.
  template <class Permutation, class Grow>
  int migrate(Store& p, Permutation& permute, Grow&& grow) {
    const Timer timer(stats_.rebuild_seconds);
    const bool moved_cuts = balance_ != SlabBalance::equal && rebalance(p);
    const int me = comm_.rank();
    for (int pass = 0;; ++pass) {
      auto x = host_copy<Paths>(p.x);
      std::vector<int> keep, down, up;
      for (int i = 0; i < p.n; ++i) {
        const int owner = owner_of(x(i, axis()));
        if (owner == me) {
          keep.push_back(i);
        } else if (owner == lower_ || (moved_cuts && owner < me)) {
          down.push_back(i);
        } else if (owner == upper_ || (moved_cuts && owner > me)) {
          up.push_back(i);
        } else {
          throw std::logic_error("a particle crossed more than one slab between list rebuilds");
        }
      }
      if (pass > 0 && !comm_.any(int(keep.size()) < p.n)) break;
      const std::vector<char> to_lower = pack_all(p, down), to_upper = pack_all(p, up);
      stats_.migrated += long(down.size() + up.size());
      if (int(keep.size()) < p.n) {
        Kokkos::View<int*, Kokkos::HostSpace> order_host("keep_order", keep.size());
        for (std::size_t k = 0; k < keep.size(); ++k) order_host(k) = keep[k];
        auto order = device_copy<Mem, Paths>(order_host);
        permute.apply(p, order, int(keep.size()));
        p.n = int(keep.size());
      }
      const NeighbourBytes arrived = exchange(to_lower, to_upper);
      unpack_all(p, arrived.lower, grow);
      unpack_all(p, arrived.upper, grow);
      if (!moved_cuts) break;
    }
    return p.n;
  }

  // Insertion on several processes: every rank placed the same new particles at rows
  // [first, p.n); keeps those whose row is this slab's (population.hpp, insert).
  template <class Permutation>
  void keep_own(Store& p, Permutation& permute, int first) {
    auto x = host_copy<Paths>(p.x);
    Kokkos::View<int*, Kokkos::HostSpace> order_host("keep_own_order", std::max(p.n, 1));
    int kept = 0;
    for (int i = 0; i < p.n; ++i)
      if (i < first || owns(x(i, axis()))) order_host(kept++) = i;
    if (kept == p.n) return;
    auto order = device_copy<Mem, Paths>(order_host);
    permute.apply(p, order, kept);
    p.n = kept;
  }

  // Appends the neighbours' boundary rows after the owned particles, which must be sorted
  // by cell (the cell sort's permutation applied: a cell is one contiguous range), and
  // returns how many, in increasing cell order. `ghost_start` receives the ghosts' cell
  // offsets (ncell + 1, relative to p.n) for the list build.
  template <class StartView, class Grow>
  int append_ghosts(Store& p, const StartView& cell_start, Kokkos::View<int*, Mem>& ghost_start,
                    Grow&& grow) {
    auto start = host_copy<Paths>(cell_start);
    send_down_ = storage_ranges(start, slabs_.first_row(comm_.rank()));
    send_up_ = storage_ranges(start, slabs_.end_row(comm_.rank()) - 1);
    // This slab's lowest row goes down, its highest up; from above comes the row above it.
    const Timer timer(stats_.rebuild_seconds);
    const NeighbourBytes in = exchange(pack_ghost(p, send_down_), pack_ghost(p, send_up_));
    from_lower_ = count_ghosts(in.lower);
    from_upper_ = count_ghosts(in.upper);
    ghosts_ = from_lower_ + from_upper_;
    const int needed = p.n + ghosts_;
    if (needed > p.capacity()) grow(needed + needed / 4);
    merge_ = merged_by_cell(in);
    unpack_merged(p, in, [](Store& s, auto&& f) { for_ghost(s, f); });
    stats_.ghosts = ghosts_;
    index_ghost_cells(p, ghost_start);
    return ghosts_;
  }

  // After a position update without a rebuild: the ghosts' new state from their owners.
  // The ghost counts are those of the rebuild, so the sizes need no message of their own.
  void update_ghosts(Store& p) {
    const Timer timer(stats_.seconds);
    const long each = long(motion_bytes());
    const NeighbourBytes in = exchange(pack_motion(p, send_down_), pack_motion(p, send_up_),
                                       ExpectedBytes{from_lower_ * each, from_upper_ * each});
    if (long(in.lower.size() + in.upper.size()) != long(ghosts_) * each)
      throw std::logic_error("a halo update brought " +
                             std::to_string((in.lower.size() + in.upper.size()) / each) +
                             " ghosts, the rebuild " + std::to_string(ghosts_));
    unpack_merged(p, in, [](Store& s, auto&& f) { for_motion(s, f); });
  }

 private:
  // Adds the wall time of one exchange (packing, transport and waiting for the neighbour
  // included) to a total of the statistics.
  struct Timer {
    double& seconds;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    explicit Timer(double& into) : seconds(into) {}
    ~Timer() {
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  };

  // In the flat cell index (CellGrid::flat): the step between cells adjacent along the
  // slab axis, and the layer across the slabs, from a cell row's cells to its next ones.
  std::pair<int, int> axis_strides() const {
    int stride = 1;
    for (int d = 0; d < axis(); ++d) stride *= grid_.ncell[d];
    return {stride, stride * grid_.ncell[axis()]};
  }

  // The storage ranges of the owned particles (sorted by cell; `start` their cell offsets)
  // in cell row `row` along the slab axis, in increasing cell order: one range for slabs
  // along y (a grid row is consecutive cells), one per grid row along x.
  template <class HostStart>
  std::vector<std::pair<int, int>> storage_ranges(const HostStart& start, int row) const {
    const auto [stride, period] = axis_strides();
    std::vector<std::pair<int, int>> out;
    for (int first = row * stride; first < grid_.total(); first += period) {
      const int begin = start(first), end = start(first + stride);
      if (end == begin) continue;
      if (!out.empty() && out.back().second == begin) {
        out.back().second = end;
      } else {
        out.emplace_back(begin, end);
      }
    }
    return out;
  }

  // The cells of the particles in one ghost message: the position is a ghost's first
  // array (for_ghost), Dim values per particle.
  static_assert(std::is_same_v<typename Store::PositionView::non_const_value_type, Position>);
  std::vector<int> cells_in(const std::vector<char>& bytes, int count) const {
    std::vector<int> cells(std::size_t(std::max(count, 0)));
    for (int k = 0; k < count; ++k) {
      int c[Dim];
      for (int d = 0; d < Dim; ++d) {
        Position x;
        std::memcpy(&x, bytes.data() + (std::size_t(k) * Dim + d) * sizeof(Position), sizeof x);
        c[d] = grid_.coord(d, x);
      }
      cells[std::size_t(k)] = grid_.flat(c);
    }
    return cells;
  }

  // The two incoming rows merged into increasing cell order, as runs of consecutive
  // particles of one message. Each arrives in its owner's cell order and their cells are
  // disjoint, so the merge keeps each cell in its owner's (cell, id) order.
  std::vector<GhostRun> merged_by_cell(const NeighbourBytes& in) const {
    const std::array<std::vector<int>, 2> cells{cells_in(in.lower, from_lower_),
                                                cells_in(in.upper, from_upper_)};
    const std::array<int, 2> count{from_lower_, from_upper_};
    std::array<int, 2> next{0, 0};
    std::vector<GhostRun> runs;
    while (next[0] < count[0] || next[1] < count[1]) {
      int from = next[0] < count[0] ? 0 : 1;
      if (next[0] < count[0] && next[1] < count[1]) {
        const int lower_cell = cells[0][std::size_t(next[0])];
        const int upper_cell = cells[1][std::size_t(next[1])];
        if (lower_cell == upper_cell)
          throw std::logic_error("a cell among the ghosts of both neighbours");
        from = lower_cell < upper_cell ? 0 : 1;
      }
      if (!runs.empty() && runs.back().from == from) {
        ++runs.back().count;
      } else {
        runs.push_back({from, next[std::size_t(from)], 1});
      }
      ++next[std::size_t(from)];
    }
    return runs;
  }

  // Writes the ghosts of both messages after the owned particles, in the merged order.
  // A message holds the arrays one after another, `count` rows each (pack_ranges).
  template <class ForArrays>
  void unpack_merged(Store& p, const NeighbourBytes& in, ForArrays&& arrays) const {
    if (ghosts_ == 0) return;
    const std::array<const std::vector<char>*, 2> bytes{&in.lower, &in.upper};
    const std::array<int, 2> count{from_lower_, from_upper_};
    std::array<std::size_t, 2> array_start{0, 0};  // the current array's bytes in each message
    arrays(p, [&](auto& view) {
      using T = typename std::decay_t<decltype(view)>::non_const_value_type;
      const std::size_t row = sizeof(T) * std::size_t(row_bytes::width(view));
      auto host = host_copy<Paths>(view);
      int at = p.n;
      for (const GhostRun& r : merge_) {
        const std::size_t from = std::size_t(r.from);
        row_bytes::extract<Paths>(
            host, bytes[from]->data() + array_start[from] + std::size_t(r.first) * row, at,
            r.count);
        at += r.count;
      }
      for (const std::size_t from : {0, 1}) array_start[from] += std::size_t(count[from]) * row;
      Kokkos::deep_copy(view, host);
    });
  }

  NeighbourBytes exchange(const std::vector<char>& to_lower, const std::vector<char>& to_upper,
                          ExpectedBytes expected = {}) {
    if (lower_ != Communicator::kNone) stats_.bytes_sent += double(to_lower.size());
    if (upper_ != Communicator::kNone) stats_.bytes_sent += double(to_upper.size());
    return comm_.exchange_with_neighbours(to_lower, lower_, to_upper, upper_, expected);
  }

  // New cuts that balance the weight per row over the ranks (every rank computes the same
  // from the same global histogram), taken when they lighten the heaviest slab by more
  // than kWorthwhile of its weight. A particle weighs 1, or (balance by work) its rank's
  // compute time per particle-step in whole picoseconds, so that the histogram sums
  // integers, exactly and alike on every rank. Returns whether the cuts moved.
  // Timings are noisy: the balance by work looks at kWorkWindow rebuilds' worth at a time
  // (rebuilds happen at the same steps on every rank, so all count alike).
  static constexpr double kWorthwhile = 0.05;
  static constexpr int kWorkWindow = 10;
  bool rebalance(const Store& p) {
    double weight = 1;
    if (balance_ == SlabBalance::work) {
      if (++rebuilds_since_check_ < kWorkWindow) return false;
      rebuilds_since_check_ = 0;
      // Until every rank has measured some work, nothing to balance by.
      const bool measured = work_particle_steps_ > 0 && work_seconds_ > 0;
      if (!comm_.all(measured)) return false;
      weight = std::max(1.0, std::round(work_seconds_ / work_particle_steps_ * 1e12));
      work_seconds_ = work_particle_steps_ = 0;
    }
    auto x = host_copy<Paths>(p.x);
    const int rows = grid_.ncell[axis()];
    std::vector<double> histogram(std::size_t(rows), 0.0);
    for (int i = 0; i < p.n; ++i)
      histogram[std::size_t(grid_.coord(axis(), x(i, axis())))] += weight;
    comm_.sum_in_place(histogram);  // integer sums below 2^53: exact in double
    const std::vector<long> per_row(histogram.begin(), histogram.end());
    const SlabDecomposition candidate = slabs_.rebalanced(per_row);
    if (double(candidate.heaviest(per_row)) >= (1 - kWorthwhile) * double(slabs_.heaviest(per_row)))
      return false;
    slabs_ = candidate;
    ++stats_.rebalances;
    return true;
  }

  // Every per-particle array travels with a migrating particle.
  template <class F>
  static void for_all(Store& p, F&& f) {
    Store::for_each_array([&](auto, auto& view) { f(view); }, p);
  }
  // A ghost: what a partner's force reads (position, velocity, species, id, spin:
  // particles/particle_store.hpp's read_by_partners).
  template <class F>
  static void for_ghost(Store& p, F&& f) {
    Store::for_each_array(
        [&](auto array, auto& view) {
          if (array.roles & read_by_partners) f(view);
        },
        p);
  }
  // Between rebuilds only what moves.
  template <class F>
  static void for_motion(Store& p, F&& f) {
    Store::for_each_array(
        [&](auto array, auto& view) {
          if (array.roles & moves) f(view);
        },
        p);
  }

  template <class ForArrays>
  static std::size_t bytes_per_particle(Store& p, ForArrays&& arrays) {
    std::size_t total = 0;
    arrays(p, [&](auto& view) {
      total += sizeof(typename std::decay_t<decltype(view)>::non_const_value_type) *
               std::size_t(row_bytes::width(view));
    });
    return total;
  }

  template <class ForArrays>
  static std::vector<char> pack_ranges(Store& p, const std::vector<std::pair<int, int>>& ranges,
                                       ForArrays&& arrays) {
    std::vector<char> out;
    arrays(p, [&](auto& view) {
      auto host = host_copy<Paths>(view);
      for (const auto& [begin, end] : ranges) row_bytes::append<Paths>(out, host, begin, end);
    });
    return out;
  }
  // Writes the particles in `bytes` at rows [first, first + count); returns count.
  template <class ForArrays>
  static int unpack_rows(Store& p, const std::vector<char>& bytes, int first, ForArrays&& arrays) {
    const std::size_t each = bytes_per_particle(p, arrays);
    const int count = int(bytes.size() / each);
    if (count == 0) return 0;
    std::size_t at = 0;
    arrays(p, [&](auto& view) {
      auto host = host_copy<Paths>(view);
      at += row_bytes::extract<Paths>(host, bytes.data() + at, first, count);
      Kokkos::deep_copy(view, host);
    });
    return count;
  }

  // The particles at storage rows `rows` (increasing), consecutive rows as one range.
  std::vector<char> pack_all(Store& p, const std::vector<int>& rows) const {
    std::vector<std::pair<int, int>> ranges;
    for (const int i : rows) {
      if (!ranges.empty() && ranges.back().second == i) {
        ++ranges.back().second;
      } else {
        ranges.emplace_back(i, i + 1);
      }
    }
    return pack_ranges(p, ranges, [](Store& s, auto&& f) { for_all(s, f); });
  }
  template <class Grow>
  void unpack_all(Store& p, const std::vector<char>& bytes, Grow& grow) const {
    const auto arrays = [](Store& s, auto&& f) { for_all(s, f); };
    const int count = int(bytes.size() / bytes_per_particle(p, arrays));
    if (p.n + count > p.capacity()) grow(p.n + count + (p.n + count) / 4);
    p.n += unpack_rows(p, bytes, p.n, arrays);
  }
  std::vector<char> pack_ghost(Store& p, const std::vector<std::pair<int, int>>& ranges) const {
    return pack_ranges(p, ranges, [](Store& s, auto&& f) { for_ghost(s, f); });
  }
  int count_ghosts(const std::vector<char>& bytes) {
    Store empty;
    return int(bytes.size() /
               bytes_per_particle(empty, [](Store& s, auto&& f) { for_ghost(s, f); }));
  }
  static std::size_t motion_bytes() {
    Store empty;
    return bytes_per_particle(empty, [](Store& s, auto&& f) { for_motion(s, f); });
  }
  std::vector<char> pack_motion(Store& p, const std::vector<std::pair<int, int>>& ranges) const {
    return pack_ranges(p, ranges, [](Store& s, auto&& f) { for_motion(s, f); });
  }

  // Cell offsets of the ghost block: ghosts are in increasing cell order (merged_by_cell).
  void index_ghost_cells(Store& p, Kokkos::View<int*, Mem>& ghost_start) const {
    const int ncell = grid_.total();
    if (int(ghost_start.extent(0)) != ncell + 1)
      ghost_start = Kokkos::View<int*, Mem>("ghost_cell_start", ncell + 1);
    auto x = host_copy<Paths>(p.x);
    auto start = host_mirror<Paths>(ghost_start);
    int g = 0;
    for (int c = 0; c <= ncell; ++c) {
      while (g < ghosts_ && grid_.cell_of(x, p.n + g) < c) ++g;
      start(c) = g;
    }
    for (int k = 1; k < ghosts_; ++k)
      if (grid_.cell_of(x, p.n + k) < grid_.cell_of(x, p.n + k - 1))
        throw std::logic_error("ghosts out of cell order");
    Kokkos::deep_copy(ghost_start, start);
  }

  const Communicator& comm_;
  Grid grid_;
  SlabDecomposition slabs_;
  SlabBalance balance_ = SlabBalance::equal;
  double work_seconds_ = 0, work_particle_steps_ = 0;  // since the last rebalance check
  int rebuilds_since_check_ = 0;
  HaloStats stats_;
  int lower_ = Communicator::kNone, upper_ = Communicator::kNone;
  // The storage ranges of the boundary rows, and the ghost block's runs (merged_by_cell),
  // as the last rebuild found them.
  std::vector<std::pair<int, int>> send_down_, send_up_;
  std::vector<GhostRun> merge_;
  int ghosts_ = 0;
  int from_lower_ = 0, from_upper_ = 0;  // ghosts from each neighbour at the last rebuild
};

}  // namespace granshock

// Field sampling on the device (docs/fields.md): every sample adds, per bin and species,
// the count and the velocity moments of the particles in it, and per bin the contact
// virial, to the sums of the current block (layout: core/bin_layout.hpp). Strategies for
// the scattered additions, measured against each other (docs/fields.md, "Cost of
// sampling"): atomic adds on one array, or a Kokkos ScatterView (one private copy per
// thread on host backends, atomics on GPUs), both here; or row owners, which compute the
// virial in the same pass (sampling/row_owner_sampling.hpp).
#pragma once

#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>

#include <stdexcept>
#include <type_traits>
#include <vector>

#include "core/bin_layout.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/device/device_math.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/device/prefetch.hpp"

namespace granshock {

// Where a position falls: flat bin index of a bin layout (grid or profile), or -1 outside.
// With `wrap` the columns tile the periodic x axis, and a position left of x0 (whose
// columns start inside the domain) lies in the last column, which wraps across the
// boundary; the clamp keeps a position that rounds onto the period's end in that column.
struct GridIndex {
  double x0, y0, inv_dx, inv_dy;
  int nx, ny;
  bool wrap;
  double z0, z1;  // 3-D: the columns' extent along z (holds_z)
  static GridIndex of(const BinLayout& l) {
    return {l.x0, l.y0, 1.0 / l.dx, 1.0 / l.dy, l.nx, l.ny, l.x_period > 0, l.z0, l.z0 + l.depth};
  }
  // 3-D: whether height z lies in the columns (all of a slab, a sphere's cut).
  KOKKOS_INLINE_FUNCTION bool holds_z(double z) const { return z >= z0 && z < z1; }
  // The row that y falls in, clamped to [0, ny].
  KOKKOS_INLINE_FUNCTION int row_of(double y) const {
    const double fy = (y - y0) * inv_dy;
    return fy < 0 ? 0 : (fy >= ny ? ny : int(fy));
  }
  // The bin, and its row in `row`.
  KOKKOS_INLINE_FUNCTION int operator()(double x, double y, int& row) const {
    double fx = (x - x0) * inv_dx;
    const double fy = (y - y0) * inv_dy;
    if (fy < 0) return -1;
    if (fx < 0) {
      if (!wrap) return -1;
      fx += nx;
    }
    const int ix = wrap && int(fx) >= nx ? nx - 1 : int(fx), iy = int(fy);
    row = iy;
    return ix >= 0 && ix < nx && iy < ny ? iy * nx + ix : -1;
  }
};

// One particle's contribution: the moments of its species and its virial, added to the
// bin it is in. `Add` is called as add(index, value).
template <class Where, class Store, class VirialView>
struct SampleContribution {
  Where where;
  Store p;
  VirialView virial;
  long block_offset;
  // A bin's quantities, and where in them the mixture's virial, a 3-D layout's z moments
  // and its W_zz start (core/bin_layout.hpp).
  int quantities, virial_at, depth_at, w_zz_at;

  static SampleContribution of(const BinLayout& l, const Where& where, const Store& p,
                               const VirialView& virial, long block_offset) {
    const bool z = l.dim == 3;
    return {where,
            p,
            virial,
            block_offset,
            l.quantities(),
            l.virial_index(BinLayout::w_xx),
            z ? l.depth_index(0, BinLayout::sum_vz) : 0,
            z ? l.w_zz_index() : 0};
  }

  template <class Add>
  KOKKOS_INLINE_FUNCTION void operator()(const int i, Add& add) const {
    int row = 0;
    if constexpr (Store::dim == 3)
      if (!where.holds_z(double(p.x(i, 2)))) return;
    const int bin = where(double(p.x(i, 0)), double(p.x(i, 1)), row);
    if (bin < 0) return;
    add_to_bin(bin, i, add, [&](int k) { return virial(i, k); });
  }

  // Fetches the lines of bin `bin` in `sums` ahead of add_to_bin (a hint, no effect on
  // the sums): a sample's bins are cold, and waiting for each in turn was over half of a
  // sample's time (docs/fields.md, "Cost of sampling").
  template <class Sums>
  KOKKOS_FORCEINLINE_FUNCTION void prefetch_bin(const Sums& sums, int bin) const {
    const double* first = &sums(block_offset + long(bin) * quantities);
    constexpr int per_line = 64 / sizeof(double);
    const double* last = first + quantities - 1;
    for (const double* line = first; line < last; line += per_line) prefetch_for_write(line);
    prefetch_for_write(last);
  }

  // Particle i's moments, and its virial terms virial_of(k) (W_ab at k = a Dim + b), added
  // to bin `bin` in the order of core/bin_layout.hpp.
  template <class Add, class VirialOf>
  KOKKOS_FORCEINLINE_FUNCTION void add_to_bin(int bin, int i, Add& add,
                                              const VirialOf& virial_of) const {
    constexpr int Dim = Store::dim;
    const long base = block_offset + long(bin) * quantities;
    const int species = p.species(i);
    const long s = base + long(BinLayout::per_species) * species;
    const double vx = p.v(i, 0), vy = p.v(i, 1);
    add(s + 0, 1.0);
    add(s + 1, vx);
    add(s + 2, vy);
    add(s + 3, vx * vx);
    add(s + 4, vx * vy);
    add(s + 5, vy * vy);
    const long w = base + virial_at;
    add(w + 0, double(virial_of(0)));        // xx
    add(w + 1, double(virial_of(1)));        // xy
    add(w + 2, double(virial_of(Dim)));      // yx
    add(w + 3, double(virial_of(Dim + 1)));  // yy
    if constexpr (Dim == 3) {
      const double vz = p.v(i, 2);
      const long z = base + depth_at + 2 * species;
      add(z, vz);
      add(z + 1, vz * vz);
      add(base + w_zz_at, double(virial_of(8)));  // zz
    }
  }
};

template <class Sums>
struct AtomicAdd {
  Sums sums;
  KOKKOS_INLINE_FUNCTION void operator()(long k, double value) const {
    Kokkos::atomic_add(&sums(k), value);
  }
};

template <class Contribution, class Sums>
struct AtomicSample {
  Contribution one;
  Sums sums;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    AtomicAdd<Sums> add{sums};
    one(i, add);
  }
};

template <class Sums>
struct PlainAdd {
  Sums sums;
  KOKKOS_INLINE_FUNCTION void operator()(long k, double value) const { sums(k) += value; }
};

template <class Access>
struct ScatterAdd {
  Access& access;
  KOKKOS_INLINE_FUNCTION void operator()(long k, double value) const { access(k) += value; }
};

template <class Contribution, class Scatter>
struct ScatterSample {
  Contribution one;
  Scatter scatter;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    auto access = scatter.access();
    ScatterAdd<decltype(access)> add{access};
    one(i, add);
  }
};

// The sums of one accumulator (grid or profile) for all blocks, on the device, and the
// per-thread scratch a ScatterView needs (sized for one block and reused).
template <class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
class BinAccumulator {
 public:
  using Mem = typename ExecSpace::memory_space;
  using Sums = Kokkos::View<double*, Mem>;
  // Host paths: Kokkos' choice for the backend (on OpenMP one private copy per thread,
  // added up after the pass). Device paths: Kokkos' choice on a GPU, one copy and atomic
  // adds.
  using Scatter = std::conditional_t<
      Paths::host,
      Kokkos::Experimental::ScatterView<double*, typename Sums::array_layout, ExecSpace>,
      Kokkos::Experimental::ScatterView<
          double*, typename Sums::array_layout, ExecSpace, Kokkos::Experimental::ScatterSum,
          Kokkos::Experimental::ScatterNonDuplicated, Kokkos::Experimental::ScatterAtomic>>;

  BinAccumulator() = default;
  BinAccumulator(long bins, int quantities, int blocks)
      : bins_(bins),
        quantities_(quantities),
        blocks_(blocks),
        sums_("field_sums", bins * quantities * blocks),
        block_("field_block", bins * quantities),
        scatter_(block_) {}

  long block_size() const { return bins_ * quantities_; }
  const Sums& sums() const { return sums_; }
  bool empty() const { return sums_.extent(0) == 0; }

  // One sample into `block` of the bins `layout` describes (the one these sums were made
  // for), `where` its index.
  template <ScatterStrategy Strategy, class Where, class Store, class VirialView>
  void sample(int block, const BinLayout& layout, const Where& where, const Store& p,
              const VirialView& virial) {
    using Policy = Kokkos::RangePolicy<ExecSpace>;
    using Contribution = SampleContribution<Where, Store, VirialView>;
    static_assert(Strategy == ScatterStrategy::atomic || Strategy == ScatterStrategy::scatter_view,
                  "row owners sample through sampling/row_owner_sampling.hpp");
    const long offset = long(block) * block_size();
    if constexpr (Strategy == ScatterStrategy::atomic) {
      const Contribution one = Contribution::of(layout, where, p, virial, offset);
      Kokkos::parallel_for("fields::sample_atomic", Policy(0, p.n),
                           AtomicSample<Contribution, Sums>{one, sums_});
    } else {
      const Contribution one = Contribution::of(layout, where, p, virial, 0);
      Kokkos::deep_copy(block_, 0.0);
      scatter_.reset_except(block_);
      Kokkos::parallel_for("fields::sample_scatter", Policy(0, p.n),
                           ScatterSample<Contribution, Scatter>{one, scatter_});
      Kokkos::Experimental::contribute(block_, scatter_);
      const auto sums = sums_, blk = block_;
      Kokkos::parallel_for(
          "fields::add_block", Policy(0, block_size()),
          KOKKOS_LAMBDA(const long k) { sums(offset + k) += blk(k); });
    }
  }

  // Threads that own bands of rows (ScatterStrategy::rows, sampling/row_owner_sampling.hpp):
  // the backend's threads, capped at 16 (each reads every particle's bins).
  // ScatterStrategy::automatic takes rows only on host paths.
  static int row_owners() {
    const int threads = ExecSpace().concurrency();
    return threads < 16 ? threads : 16;
  }
  static ScatterStrategy resolve(ScatterStrategy s) {
    if (s != ScatterStrategy::automatic) return s;
    return Paths::host && ExecSpace().concurrency() <= 16 ? ScatterStrategy::rows
                                                          : ScatterStrategy::atomic;
  }

  std::vector<double> to_host() const {
    const auto h = host_copy<Paths>(sums_);
    return std::vector<double>(h.data(), h.data() + h.extent(0));
  }
  // The sums `values`, or zeros of their size (take = false: a rank other than the one
  // that holds the global sums).
  void from_host(const std::vector<double>& values, bool take = true) {
    if (values.size() != sums_.extent(0))
      throw std::runtime_error("field sums of the checkpoint do not match the scene's bins");
    if (!take) {
      Kokkos::deep_copy(sums_, 0.0);
      return;
    }
    auto h = host_mirror<Paths>(sums_);
    for (std::size_t k = 0; k < values.size(); ++k) h(k) = values[k];
    Kokkos::deep_copy(sums_, h);
  }

 private:
  long bins_ = 0;
  int quantities_ = 0, blocks_ = 0;
  Sums sums_, block_;
  Scatter scatter_;
};

}  // namespace granshock

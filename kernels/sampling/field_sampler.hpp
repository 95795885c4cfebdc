// Field sampling of one compiled variant (docs/fields.md, "Sampling" and "Cost of
// sampling"): the bin sums of the grid and of the stagnation-line profile, and the three
// ways a sample is scattered into them (core/bin_layout.hpp): atomics, a ScatterView, or
// row owners (row_owner_sampling.hpp). The solver hands it the particles and their contact
// virial, which the step's last force pass recorded (docs/fields.md, "The contact
// virial"), or, where no pass recorded it, the force kernel in virial mode to compute it
// first; the sampler owns the sums and its scratch arrays.
#pragma once

#include <Kokkos_Core.hpp>
#include <vector>

#include "kernels/device/space_alloc.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/sampling/bin_accumulator.hpp"
#include "kernels/sampling/row_owner_sampling.hpp"
#include "kernels/solver/contact_forces.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths>
class FieldSampler {
 public:
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Mem = typename Types::Mem;
  using Store = typename Types::Store;
  using Accumulator = BinAccumulator<ExecSpace, Paths>;
  using VirialKernel = ContactForceKernel<V, ExecSpace, ForceMode::virial>;
  using VirialView = typename Store::VirialView;
  using Policy = Kokkos::RangePolicy<ExecSpace>;

  void configure(const FieldSampling& f) {
    sampling_ = f;
    grid_sums_ = Accumulator(f.grid.bins(), f.grid.quantities(), f.grid.blocks);
    if (f.has_profile()) {
      // The same quantities per bin (species and dimension) as the grid: the run file and
      // the analysis read both with the grid's layout.
      if (f.profile.quantities() != f.grid.quantities())
        throw std::logic_error("field sampling: the profile's bins hold other quantities");
      profile_sums_ = Accumulator(f.profile.bins(), f.grid.quantities(), f.grid.blocks);
    }
  }

  // One sample of p's particles into `block`, with `virial` their contact virial.
  void sample(int block, const Store& p, const VirialView& virial) {
    const GridIndex grid = GridIndex::of(sampling_.grid);
    const GridIndex profile = GridIndex::of(sampling_.profile);
    const ScatterStrategy strategy = Accumulator::resolve(sampling_.strategy);
    if (strategy == ScatterStrategy::rows) {
      sample_by_row_owners(block, grid, profile, p, virial);
    } else if (strategy == ScatterStrategy::atomic) {
      sample_with<ScatterStrategy::atomic>(block, grid, profile, p, virial);
    } else {
      sample_with<ScatterStrategy::scatter_view>(block, grid, profile, p, virial);
    }
  }

  // The same where no force pass recorded the virial: `contacts`, the force kernel in
  // virial mode over the same particles, computes it first (its virial view is the
  // sampler's to set).
  void sample_computing_virial(int block, const Store& p, VirialKernel contacts) {
    if (int(virial_.extent(0)) < p.n)
      virial_ = VirialView(alloc_on<ExecSpace>("virial"), p.capacity());
    contacts.virial = virial_;
    Kokkos::parallel_for("contact_virial", Policy(0, p.n), contacts);
    sample(block, p, virial_);
  }

  // The process's own sums of the grid or the profile, on the host.
  std::vector<double> to_host(bool profile) const {
    return profile ? profile_sums_.to_host() : grid_sums_.to_host();
  }
  // Sums read from a checkpoint; a process that is not `mine` starts from zero.
  void from_host(const std::vector<double>& grid, const std::vector<double>& profile, bool mine) {
    grid_sums_.from_host(grid, mine);
    if (!profile_sums_.empty()) profile_sums_.from_host(profile, mine);
  }

 private:
  template <ScatterStrategy Strategy>
  void sample_with(int block, const GridIndex& grid, const GridIndex& profile, const Store& p,
                   const VirialView& virial) {
    grid_sums_.template sample<Strategy>(block, sampling_.grid, grid, p, virial);
    if (!profile_sums_.empty())
      profile_sums_.template sample<Strategy>(block, sampling_.profile, profile, p, virial);
  }

  // Grid and profile in one pass (row_owner_sampling.hpp).
  void sample_by_row_owners(int block, const GridIndex& grid, const GridIndex& profile,
                            const Store& p, const VirialView& virial) {
    using Part = SampleContribution<GridIndex, Store, VirialView>;
    const Part grid_part =
        Part::of(sampling_.grid, grid, p, virial, block * grid_sums_.block_size());
    const Part profile_part =
        Part::of(sampling_.profile, profile, p, virial, block * profile_sums_.block_size());
    if (int(sample_bins_.extent(0)) < p.n)
      sample_bins_ = decltype(sample_bins_)(alloc_on<ExecSpace>("sample_bins"), p.capacity());
    Kokkos::parallel_for("fields::locate", Policy(0, p.n),
                         LocateSampleBins<decltype(p.x), decltype(sample_bins_), Dim>{
                             grid, profile, !profile_sums_.empty(), p.x, sample_bins_});
    const int owners = Accumulator::row_owners();
    const RowOwnerSamplePass<ExecSpace, Part, decltype(p.x), decltype(sample_bins_)> pass{
        grid_part, profile_part, grid_sums_.sums(), profile_sums_.sums(), p.x, sample_bins_,
        p.n,       owners};
    Kokkos::parallel_for("fields::sample_rows", Policy(0, owners), pass);
  }

  FieldSampling sampling_;
  Accumulator grid_sums_, profile_sums_;
  VirialView virial_;                        // sample_computing_virial's
  Kokkos::View<int* [2], Mem> sample_bins_;  // row-owner sampling: each particle's bins
};

}  // namespace granshock

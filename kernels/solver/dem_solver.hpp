// DemSolver: the DEM solver of one compiled variant (docs/design.md, "The solver"), the
// Solver interface (core/solver.hpp) over its parts:
//   solver_parts.hpp     what it holds: geometry, pair table, particles, lists, counters;
//   step_loop.hpp        the time loop: first half-step -> [rebuild lists if some particle
//                        moved > skin/2] -> forces -> second half-step, the last three and
//                        the next first half fused into one pass, in Kokkos kernels;
//   list_keeping.hpp     when and how the neighbour lists are rebuilt;
//   state_transfer.hpp   particles, snapshots and checkpoint states in and out;
// with population control (particles/population.hpp), field sampling
// (sampling/field_sampler.hpp) and diagnostics (diagnostics.hpp). Host copies happen only
// on request (snapshots, diagnostics) and for the one scalar that decides a rebuild, which
// goes through the Communicator like every other global reduction.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/communicator.hpp"
#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/solver/list_keeping.hpp"
#include "kernels/solver/solver_parts.hpp"
#include "kernels/solver/state_transfer.hpp"
#include "kernels/solver/step_loop.hpp"

namespace granshock {

// Paths: where the kernels take their host or their device branches (device/backends.hpp;
// docs/cuda.md, "Branch points"); a test may build the other way to compare the two.
template <class V, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
class DemSolver final : public Solver {
  static_assert(paths_possible<ExecSpace, Paths>(), "host paths need host-accessible memory");

 public:
  DemSolver(const SolverSetup& setup, std::size_t capacity, const Communicator& comm)
      : s_(setup, capacity, comm), lists_(s_), loop_(s_, lists_), state_(s_, lists_) {}

  // Stepping ----------------------------------------------------------------------------
  void set_particles(const HostParticles& given) override {
    state_.set_particles(given);
    rebuild_lists();
    loop_.compute_forces();
  }
  void rebuild_lists() override { lists_.rebuild(); }
  void advance(long steps) override { loop_.advance(steps); }

  // Several processes: every rank places the same particles (population.hpp) and keeps
  // its slab's; the count returned is the whole event's, the same on every rank. New
  // particles overwrite the ghost rows, so a caller that defers the rebuild
  // (rebuild_lists = false) must rebuild before the next step, as it must anyway.
  int insert(const InsertionRequest& request) override {
    const int before = s_.p.n;
    const int placed = s_.population.insert(s_.p, request, s_.slabs ? &s_.comm : nullptr);
    if (s_.slabs && placed > 0) s_.slabs->keep_own(s_.p, s_.permutation, before);
    if (request.count > 0 && request.rebuild_lists) rebuild_lists();
    return placed;
  }
  RemovalCounts remove_escaped() override {
    rebuild_lists();
    return removed();
  }
  // Several processes: each counts its own deletions; one sum over ranks (exact: counts).
  RemovalCounts removed() const override {
    RemovalCounts r = s_.population.removed();
    if (!s_.slabs) return r;
    std::vector<double> counts{r.low.begin(), r.low.end()};
    counts.insert(counts.end(), r.high.begin(), r.high.end());
    s_.comm.sum_in_place(counts);
    for (int d = 0; d < 3; ++d) {
      r.low[d] = long(counts[d]);
      r.high[d] = long(counts[3 + d]);
    }
    return r;
  }
  int next_id() const override { return s_.population.next_id(); }

  void decompose(const Decomposition& d) override {
    if (!s_.slabs) return;
    if (s_.slabs->axis() != int(d.axis)) {
      if (s_.p.n > 0 || s_.builds > 0)
        throw std::logic_error("the slab axis is chosen before any particle is placed");
      s_.slabs.emplace(s_.comm, s_.grid, s_.setup.box, int(d.axis));
    }
    s_.slabs->set_balance(d.balance);
  }

  std::size_t size() const override { return std::size_t(s_.p.n); }
  long global_size() const override { return s_.comm.sum(long(s_.p.n)); }
  double skin() const override { return double(s_.skin); }
  double time() const override { return double(s_.steps) * s_.setup.dt; }
  // A host backend on device paths says so (docs/cuda.md, "Branch points").
  std::string variant() const override {
    const bool device_paths_on_host = !Paths::host && host_accessible<ExecSpace>();
    return V::name() + "/" + ExecSpace::name() + (device_paths_on_host ? "/device-paths" : "");
  }

  // Field sampling ----------------------------------------------------------------------
  // 3-D: refused until the bins keep the z moments and the virial's 3 x 3 terms (the
  // bins' layout, core/bin_layout.hpp, holds the x-y ones: docs/design.md, "Dimension").
  void configure_sampling(const FieldSampling& f) override {
    // The bins' quantities follow the dimension (core/bin_layout.hpp).
    if (f.grid.dim != V::dim || (f.has_profile() && f.profile.dim != V::dim))
      throw std::logic_error("field sampling laid out for dimension " + std::to_string(f.grid.dim) +
                             " in a " + std::to_string(V::dim) + "-D solver");
    s_.sampler.configure(f);
  }

  // The virial of the last force pass where it recorded one at this step; otherwise (a
  // state from a checkpoint that held none) computed here, at the current velocities.
  void sample_fields(int block) override {
    if (s_.virial_recorded) {
      s_.sampler.sample(block, s_.p, s_.p.virial);
    } else {
      s_.sampler.sample_computing_virial(
          block, s_.p, loop_.template force_kernel<ForceMode::virial>(s_.p, s_.pair_loop()));
    }
  }
  std::vector<double> field_sums(bool profile) const override {
    std::vector<double> sums = s_.sampler.to_host(profile);
    s_.comm.sum_in_place(sums);
    return sums;
  }
  // The sums are global (field_sums adds over ranks): rank 0 takes them, the others zero.
  void restore_field_sums(const std::vector<double>& grid,
                          const std::vector<double>& profile) override {
    s_.sampler.from_host(grid, profile, !s_.slabs || s_.comm.is_root());
  }

  // State in and out --------------------------------------------------------------------
  HostParticles particles() const override { return state_.particles(); }
  SnapshotPart snapshot_part() const override { return state_.snapshot_part(); }
  SolverState export_state() const override { return state_.export_state(removed()); }
  void import_state(const SolverState& state) override { state_.import_state(state); }

  // Statistics --------------------------------------------------------------------------
  Diagnostics diagnostics() const override { return s_.diagnostics().compute(s_.comm); }
  std::vector<std::pair<int, int>> contact_pairs() const override {
    return s_.diagnostics().contact_pairs();
  }
  std::vector<SpeciesMoments> species_moments() const override {
    return s_.diagnostics().species_moments(int(s_.setup.species.size()), s_.comm);
  }
  HaloStats halo_stats() const override {
    if (!s_.slabs) return HaloStats{};
    HaloStats h = s_.slabs->stats();
    h.sync_seconds = s_.sync_seconds;
    return h;
  }
  long steps_done() const override { return s_.steps; }
  long list_builds() const override { return s_.builds; }
  long exact_list_checks() const override { return s_.exact_checks; }
  long step_regions() const override { return s_.step_regions; }
  ThreadShareStats thread_shares() const override { return s_.thread_shares.stats(); }

 private:
  SolverParts<V, ExecSpace, Paths> s_;
  ListKeeping<V, ExecSpace, Paths> lists_;
  StepLoop<V, ExecSpace, Paths> loop_;
  StateTransfer<V, ExecSpace, Paths> state_;
};

}  // namespace granshock

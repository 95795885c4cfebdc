// DemSolver: one compiled variant of the DEM time loop. It owns the particles, the
// cell sort, the Verlet list and (with friction) the contact history, and runs
//   first half-step -> [rebuild lists if some particle moved > skin/2] -> forces ->
//   second half-step
// entirely in Kokkos kernels on ExecSpace. Host copies happen only on request
// (snapshots, diagnostics) and for the one scalar that decides a rebuild.
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <stdexcept>

#include "bin_accumulator.hpp"
#include "cell_grid.hpp"
#include "cell_sort.hpp"
#include "checkpoint_checks.hpp"
#include "contact_forces.hpp"
#include "contact_history.hpp"
#include "device_lambda.hpp"
#include "particle_population.hpp"
#include "reorder.hpp"
#include "scene_traits.hpp"
#include "solver.hpp"
#include "species_table.hpp"
#include "user_error.hpp"
#include "velocity_verlet.hpp"
#include "verlet_list.hpp"

namespace granshock {

template <class Traits, class ExecSpace>
class DemSolver final : public Solver {
 public:
  static constexpr int Dim = Traits::dim;
  using Real = typename Traits::real;
  using Mem = typename ExecSpace::memory_space;
  using Policy = Kokkos::RangePolicy<ExecSpace>;
  using Store = ParticleStore<Dim, Real, Mem>;

  DemSolver(const SystemSetup& setup, std::size_t capacity)
      : setup_(validated(setup)),
        table_(SpeciesTable<Real, Mem>::build(setup)),
        box_(BoxGeometry<Dim, Real>::from(setup.box)),
        skin_(Real(setup.skin())),
        grid_(CellGrid<Dim, Real>::make(setup.box, setup.max_diameter() + setup.skin())) {
    integrator_.dt = Real(setup.dt);
    for (int d = 0; d < Dim; ++d) integrator_.gravity[d] = Real(setup.gravity[d]);
    if constexpr (Traits::obstacle) {
      for (int d = 0; d < Dim; ++d) cylinder_.centre[d] = Real(setup.obstacle->centre[d]);
      cylinder_.radius = Real(0.5 * setup.obstacle->diameter_m);
    } else {
      cylinder_.centre = Vec<Dim, Real>::zero();
      cylinder_.radius = 0;
    }
    for (int d = 0; d < Dim; ++d) {
      escape_.test.lo[d] = Real(setup.box.lo[d]);
      escape_.test.hi[d] = Real(setup.box.hi[d]);
      escape_.test.check[d] = setup.delete_outside && !setup.box.periodic[d];
      escape_.check_any = escape_.check_any || escape_.test.check[d];
    }
    allocate(int(std::max<std::size_t>(capacity, 1)));
  }

  void set_particles(const HostParticles& hp) override {
    const int n = int(hp.size());
    if (n > p_.capacity()) allocate(n + n / 4);
    auto x = Kokkos::create_mirror_view(p_.x);
    auto v = Kokkos::create_mirror_view(p_.v);
    auto species = Kokkos::create_mirror_view(p_.species);
    auto id = Kokkos::create_mirror_view(p_.id);
    auto omega = Kokkos::create_mirror_view(p_.omega);
    for (int i = 0; i < n; ++i) {
      for (int d = 0; d < Dim; ++d) {
        x(i, d) = Real(hp.position[i][d]);
        v(i, d) = Real(hp.velocity[i][d]);
      }
      if (hp.species[i] < 0 || hp.species[i] >= int(setup_.species.size()))
        throw UserError("particle " + std::to_string(hp.id[i]) + " has unknown species " +
                        std::to_string(hp.species[i]));
      species(i) = hp.species[i];
      id(i) = hp.id[i];
      if constexpr (Traits::friction)
        omega(i) = hp.angular_velocity.empty() ? Real(0) : Real(hp.angular_velocity[i]);
    }
    Kokkos::deep_copy(p_.x, x);
    Kokkos::deep_copy(p_.v, v);
    Kokkos::deep_copy(p_.species, species);
    Kokkos::deep_copy(p_.id, id);
    Kokkos::deep_copy(p_.omega, omega);
    p_.n = n;
    next_id_ = 0;
    for (int i = 0; i < n; ++i) next_id_ = std::max(next_id_, hp.id[i] + 1);
    Kokkos::deep_copy(p_.f, Real(0));
    if constexpr (Traits::friction) {
      Kokkos::deep_copy(history_.partner, -1);
      Kokkos::deep_copy(history_.spring, Real(0));
      Kokkos::deep_copy(history_.wall_spring, Real(0));
    }
    rebuild_lists();
    compute_forces();
  }

  HostParticles particles() const override {
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.x);
    auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.v);
    auto species = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.species);
    auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.id);
    auto omega = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.omega);
    HostParticles hp;
    for (int i = 0; i < p_.n; ++i) {
      std::array<double, 3> xi{0, 0, 0}, vi{0, 0, 0};
      for (int d = 0; d < Dim; ++d) {
        xi[d] = x(i, d);
        vi[d] = v(i, d);
      }
      hp.add(xi, vi, species(i), id(i));
      if constexpr (Traits::friction) hp.angular_velocity.push_back(omega(i));
    }
    return hp;
  }

  void advance(long steps) override {
    const Real rebuild_d2 = Real(0.25) * skin_ * skin_;  // (skin/2)^2
    for (long s = 0; s < steps; ++s) {
      if (integrator_.first_half(p_, table_, x_ref_) > rebuild_d2) rebuild_lists();
      compute_forces();
      integrator_.second_half(p_, table_);
      ++steps_;
    }
    if constexpr (Traits::friction) {
      int overflow = 0;
      Kokkos::deep_copy(overflow, history_.overflow);
      if (overflow)
        throw std::runtime_error("a particle had more than " +
                                 std::to_string(ContactHistory<Dim, Real, Mem>::slots) +
                                 " simultaneous contacts: the packing is unphysically dense "
                                 "(huge overlaps?); reduce dt or check the scene");
    }
  }

  Diagnostics diagnostics() const override;
  std::vector<std::pair<int, int>> contact_pairs() const override;

  std::size_t size() const override { return std::size_t(p_.n); }
  long steps_done() const override { return steps_; }
  long list_builds() const override { return builds_; }
  double time() const override { return double(steps_) * setup_.dt; }
  std::string variant() const override { return Traits::name() + "/" + ExecSpace::name(); }

  RemovalCounts remove_escaped() override {
    rebuild_lists();
    return removed_;
  }
  RemovalCounts removed() const override { return removed_; }
  int next_id() const override { return next_id_; }

  int insert(const InsertionRequest& request) override;
  // One round of insert(); public because it launches KOKKOS_LAMBDAs (nvcc).
  int insert_round(const InsertionRequest& request, int placed, int wanted, int candidates,
                   long first_candidate);
  static constexpr int kInsertionRounds = 16;
  std::vector<SpeciesMoments> species_moments() const override;
  SolverState export_state() const override;
  // Refuses (InvalidCheckpoint, nothing changed) a state that does not fit this solver.
  void import_state(const SolverState& state) override;

  // Wraps periodic coordinates, deletes escaped particles, sorts by cell and rebuilds
  // the Verlet list; x_ref remembers where particles were, for the skin criterion.
  void rebuild_lists() {
    wrap_periodic();
    if (escape_.check_any) remove_escaped_now();
    sort_.sort(grid_, p_.x, p_.id, p_.n);
    permute(sort_.order, p_.n);
    list_.build(grid_, box_, sort_.cell_start, p_.x, p_.species, table_.radius, skin_, p_.n);
    Kokkos::deep_copy(x_ref_, p_.x);
    ++builds_;
  }

  void compute_forces() {
    ContactForceKernel<Traits, ExecSpace> kernel{
        p_,        list_.offsets, list_.neighbours, table_, box_,
        cylinder_, history_,      Real(setup_.dt),  {}};
    Kokkos::parallel_for("contact_forces", Policy(0, p_.n), kernel);
  }

  void configure_sampling(const FieldSampling& f) override {
    sampling_ = f;
    grid_sums_ = BinAccumulator<ExecSpace>(f.grid.bins(), f.grid.quantities(), f.grid.blocks);
    if (f.profile.n > 0)
      profile_sums_ = BinAccumulator<ExecSpace>(f.profile.n, f.grid.quantities(), f.grid.blocks);
  }

  void sample_fields(int block) override {
    if (int(virial_.extent(0)) < p_.n) virial_ = decltype(virial_)("virial", p_.capacity());
    ContactForceKernel<Traits, ExecSpace, ForceMode::virial> kernel{
        p_,        list_.offsets, list_.neighbours, table_, box_,
        cylinder_, history_,      Real(setup_.dt),  virial_};
    Kokkos::parallel_for("contact_virial", Policy(0, p_.n), kernel);
    const BinLayout& g = sampling_.grid;
    const GridIndex grid{g.x0, g.y0, 1.0 / g.bin_size, g.nx, g.ny};
    const ProfileLayout& pr = sampling_.profile;
    const ProfileIndex profile{pr.x_lo, pr.x_hi, pr.y0, 1.0 / pr.dy, pr.n};
    if (sampling_.strategy == ScatterStrategy::atomic) {
      grid_sums_.template sample<ScatterStrategy::atomic>(block, grid, p_, virial_);
      if (!profile_sums_.empty())
        profile_sums_.template sample<ScatterStrategy::atomic>(block, profile, p_, virial_);
    } else {
      grid_sums_.template sample<ScatterStrategy::scatter_view>(block, grid, p_, virial_);
      if (!profile_sums_.empty())
        profile_sums_.template sample<ScatterStrategy::scatter_view>(block, profile, p_, virial_);
    }
  }

  std::vector<double> field_sums(bool profile) const override {
    return profile ? profile_sums_.to_host() : grid_sums_.to_host();
  }
  void restore_field_sums(const std::vector<double>& grid,
                          const std::vector<double>& profile) override {
    grid_sums_.from_host(grid);
    if (!profile_sums_.empty()) profile_sums_.from_host(profile);
  }

  // Public because it launches a KOKKOS_LAMBDA: nvcc rejects an extended lambda whose
  // enclosing member function is private or protected.
  void wrap_periodic() {
    const auto box = box_;
    const auto x = p_.x;
    Kokkos::parallel_for(
        "wrap_periodic", Policy(0, p_.n), KOKKOS_LAMBDA(const int i) {
          for (int d = 0; d < Dim; ++d) x(i, d) = box.wrap(d, x(i, d));
        });
  }

  // Public for the same reason (nvcc and KOKKOS_LAMBDA).
  template <class View>
  static void copy_prefix(const View& dst, const View& src, int n) {
    if (src.extent(0) == 0 || n == 0) return;
    Kokkos::parallel_for(
        "copy_prefix", Policy(0, n), KOKKOS_LAMBDA(const int i) {
          capture_before_if_constexpr(dst, src);
          if constexpr (View::rank == 1) {
            dst(i) = src(i);
          } else {
            for (int c = 0; c < int(src.extent(1)); ++c) dst(i, c) = src(i, c);
          }
        });
  }

 private:
  static const SystemSetup& validated(const SystemSetup& s) {
    if (s.species.empty()) throw UserError("a scene needs at least one species");
    if (!(s.max_diameter() > 0)) throw UserError("particle diameters must be > 0");
    if (Traits::obstacle != s.obstacle.has_value())
      throw std::logic_error("DemSolver variant does not match the scene's obstacle");
    return s;
  }

  SolverFit fit() const;
  void check_lists(const SolverState& s) const;

  void allocate(int capacity) {
    p_.allocate(capacity, Traits::friction);
    x_ref_ = decltype(x_ref_)("x_ref", capacity);
    if constexpr (Traits::friction) history_.allocate(capacity);
  }

  // Grows the arrays to `capacity`, keeping the n owned particles (rare: only when an
  // insertion needs more room than the scene's estimate).
  void grow(int capacity) {
    const Store old = p_;
    const auto old_ref = x_ref_;
    const auto old_history = history_;
    allocate(capacity);
    p_.n = old.n;
    copy_prefix(p_.x, old.x, old.n);
    copy_prefix(p_.v, old.v, old.n);
    copy_prefix(p_.f, old.f, old.n);
    copy_prefix(p_.omega, old.omega, old.n);
    copy_prefix(p_.torque, old.torque, old.n);
    copy_prefix(p_.species, old.species, old.n);
    copy_prefix(p_.id, old.id, old.n);
    copy_prefix(x_ref_, old_ref, old.n);
    if constexpr (Traits::friction) {
      copy_prefix(history_.partner, old_history.partner, old.n);
      copy_prefix(history_.spring, old_history.spring, old.n);
      copy_prefix(history_.wall_spring, old_history.wall_spring, old.n);
    }
  }

  // Reorders every per-particle array: new index k holds old particle order(k).
  template <class OrderView>
  void permute(const OrderView& order, int n) {
    gather_in_place<ExecSpace>(p_.x, scratch_vec_, order, n);
    gather_in_place<ExecSpace>(p_.v, scratch_vec_, order, n);
    gather_in_place<ExecSpace>(p_.f, scratch_vec_, order, n);
    gather_in_place<ExecSpace>(x_ref_, scratch_vec_, order, n);
    gather_in_place<ExecSpace>(p_.species, scratch_int_, order, n);
    gather_in_place<ExecSpace>(p_.id, scratch_int_, order, n);
    if constexpr (Traits::friction) {
      gather_in_place<ExecSpace>(p_.omega, scratch_real_, order, n);
      gather_in_place<ExecSpace>(p_.torque, scratch_real_, order, n);
      gather_in_place<ExecSpace>(history_.partner, scratch_partner_, order, n);
      gather_in_place<ExecSpace>(history_.spring, scratch_spring_, order, n);
      gather_in_place<ExecSpace>(history_.wall_spring, scratch_vec_, order, n);
    }
  }

  void remove_escaped_now() {
    if (int(keep_order_.extent(0)) < p_.capacity())
      keep_order_ = Kokkos::View<int*, Mem>("keep_order", p_.capacity());
    long per_face[2 * Dim];
    const int kept =
        compact_escaped<Dim, Real, ExecSpace>(escape_.test, p_.x, p_.n, keep_order_, per_face);
    if (kept == p_.n) return;
    for (int d = 0; d < Dim; ++d) {
      removed_.low[d] += per_face[2 * d];
      removed_.high[d] += per_face[2 * d + 1];
    }
    permute(keep_order_, kept);
    p_.n = kept;
  }

  SystemSetup setup_;
  SpeciesTable<Real, Mem> table_;
  BoxGeometry<Dim, Real> box_;
  Real skin_;
  CellGrid<Dim, Real> grid_;
  CylinderGeometry<Dim, Real> cylinder_;
  VelocityVerlet<Traits, ExecSpace> integrator_;

  Store p_;
  Kokkos::View<Real* [Dim], Mem> x_ref_;
  ContactHistory<Dim, Real, Mem> history_;
  CellSort<Dim, Real, ExecSpace> sort_;
  VerletList<Dim, Real, ExecSpace> list_;

  typename Store::VectorView scratch_vec_;
  typename Store::ScalarView scratch_real_;
  typename Store::IntView scratch_int_;
  decltype(history_.partner) scratch_partner_;
  decltype(history_.spring) scratch_spring_;

  struct {
    EscapeTest<Dim, Real> test;
    bool check_any = false;
  } escape_;
  Kokkos::View<int*, Mem> keep_order_;
  FieldSampling sampling_;
  BinAccumulator<ExecSpace> grid_sums_, profile_sums_;
  Kokkos::View<Real * [Dim * Dim], Mem> virial_;
  RemovalCounts removed_;
  int next_id_ = 0;
  long steps_ = 0;
  long builds_ = 0;
};

}  // namespace granshock

#include "dem_solver_diagnostics.hpp"
#include "dem_solver_population.hpp"
#include "dem_solver_state.hpp"

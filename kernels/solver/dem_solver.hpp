// DemSolver: the DEM time loop of one compiled variant (docs/design.md, "The solver"):
//   first half-step -> [rebuild lists if some particle moved > skin/2] -> forces ->
//   second half-step, with the last three and the next first half fused into one pass
// entirely in Kokkos kernels on ExecSpace. It owns the particles (particles/), the cell
// sort and Verlet list (neighbours/); field sampling (sampling/field_sampler.hpp),
// population control, diagnostics and state I/O are parts of their own (population.hpp,
// diagnostics.hpp, state_io.hpp). Host copies happen only on request
// (snapshots, diagnostics) and for the one scalar that decides a rebuild, which goes
// through the Communicator like every other global reduction.
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "core/checkpoint_checks.hpp"
#include "core/communicator.hpp"
#include "core/particle_bytes.hpp"
#include "core/skin_model.hpp"
#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/device/space_alloc.hpp"
#include "kernels/neighbours/cell_grid.hpp"
#include "kernels/neighbours/cell_sort.hpp"
#include "kernels/neighbours/pair_loop.hpp"
#include "kernels/neighbours/rebuild_watch.hpp"
#include "kernels/neighbours/verlet_list.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/population.hpp"
#include "kernels/particles/slab_exchange.hpp"
#include "kernels/particles/slab_state.hpp"
#include "kernels/sampling/field_sampler.hpp"
#include "kernels/solver/contact_forces.hpp"
#include "kernels/solver/diagnostics.hpp"
#include "kernels/solver/fused_step.hpp"
#include "kernels/solver/fused_steps.hpp"
#include "kernels/solver/obstacle_runs.hpp"
#include "kernels/solver/pair_table.hpp"
#include "kernels/solver/state_io.hpp"
#include "kernels/solver/velocity_verlet.hpp"

namespace granshock {

// Paths: where the kernels take their host or their device branches (device/backends.hpp;
// docs/cuda.md, "Branch points"); a test may build the other way to compare the two.
template <class V, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
class DemSolver final : public Solver {
  static_assert(paths_possible<ExecSpace, Paths>(), "host paths need host-accessible memory");

 public:
  static constexpr int Dim = V::dim;
  using Real = typename V::real;
  using Model = typename V::model;
  using Mem = typename ExecSpace::memory_space;
  using Policy = Kokkos::RangePolicy<ExecSpace>;
  using Store = ParticleStore<Dim, Real, Mem, V::friction>;
  using Obstacle = typename V::obstacle::template Geometry<Dim, Real>;
  // Positions, the box, cells and the skin displacement are in Position (double) in every
  // variant; the rest in Real (device/position.hpp; docs/design.md, "Particles").
  using Position = typename Store::Position;
  using Population = ParticlePopulation<V, ExecSpace, Paths>;

  DemSolver(const SolverSetup& setup, std::size_t capacity, const Communicator& comm)
      : setup_(validated(setup)),
        comm_(comm),
        table_(PairTable<Model, Real, Mem>::template build<Paths>(setup)),
        box_(BoxGeometry<Dim, Position>::from(setup.box)),
        obstacle_(Obstacle::from(setup.obstacle)),
        skin_(Real(setup.skin())),
        grid_(CellGrid<Dim, Position>::make(setup.box, setup.max_diameter() + setup.skin())),
        population_(setup, box_, obstacle_),
        history_overflow_("history_overflow"),
        watch_(0.5 * double(skin_), double(Real(setup.dt))),
        skin_model_{Dim, setup.max_diameter(), grid_.mean_cell_size(),
                    setup.smallest_adaptive_skin(), setup.skin()} {
    integrator_.dt = Real(setup.dt);
    for (int d = 0; d < Dim; ++d) integrator_.gravity[d] = Real(setup.gravity[d]);
    p_.allocate(int(std::max<std::size_t>(capacity, 1)));
    list_.visit_once = setup.list_visits_once;
    if (comm.size() > 1) slabs_.emplace(comm, grid_, setup.box, int(Decomposition{}.axis));
  }

  // Several processes: each keeps the particles of its slab (every rank is given all).
  void set_particles(const HostParticles& given) override {
    const HostParticles hp = slabs_ ? slab_state::mine<Position>(given, *slabs_) : given;
    int next_id = 0;
    for (const int id : given.id) next_id = std::max(next_id, id + 1);
    const int n = int(hp.size());
    for (std::size_t i = 0; i < hp.size(); ++i)
      if (hp.species[i] < 0 || hp.species[i] >= int(setup_.species.size()))
        throw UserError("particle " + std::to_string(hp.id[i]) + " has unknown species " +
                        std::to_string(hp.species[i]));
    if (n > p_.capacity()) p_.allocate(n + n / 4);
    state_io::import_given<Paths, Store, Dim>(p_, hp);
    population_.restore(next_id, population_.removed());
    rebuild_lists();
    compute_forces();
  }

  HostParticles particles() const override {
    auto x = host_copy<Paths>(p_.x);
    auto v = host_copy<Paths>(p_.v);
    auto species = host_copy<Paths>(p_.species);
    auto id = host_copy<Paths>(p_.id);
    auto omega = host_copy<Paths>(p_.omega);
    HostParticles hp;
    for (int i = 0; i < p_.n; ++i) {
      std::array<double, 3> xi{0, 0, 0}, vi{0, 0, 0};
      for (int d = 0; d < Dim; ++d) {
        xi[d] = x(i, d);
        vi[d] = v(i, d);
      }
      hp.add(xi, vi, species(i), id(i));
      if constexpr (V::friction) hp.angular_velocity.push_back(omega(i));
    }
    return hp;
  }

  // Velocity Verlet, steps times. Inside the loop the second half of step n, the first
  // half of n+1 and the forces between them are one fused pass (fused_step.hpp); the
  // first step starts with the first half and the last ends with forces and the second
  // half, so between calls x, v and f belong to the same step, as with separate halves.
  // That last force pass also records each particle's contact virial, which a field
  // sample at this step reads (compute_forces).
  void advance(long steps) override {
    if (steps <= 0) return;
    const WorkClock work = start_work_clock();
    watch_.measured(global_max(integrator_.first_half(p_, table_)));
    for (long s = 0; s < steps; ++s) {
      if (list_expired()) {
        if (setup_.adaptive_skin) choose_skin();
        rebuild_lists();
      } else if (slabs_) {
        slabs_->update_ghosts(p_);
      }
      if (s + 1 < steps) {
        const bool by_speed = !setup_.exact_list_check && watch_.next_drift_by_speed();
        if (by_speed && steps_in_one_region()) {
          const long done = fused_steps(std::min(steps - 1 - s, setup_.steps_per_region));
          s += done - 1;  // the loop counts the last
          steps_ += done - 1;
        } else {
          const double reported = global_max(fused_step(by_speed));
          if (by_speed) {
            watch_.drifted(reported);
          } else {
            watch_.measured(reported);
          }
        }
      } else {
        compute_forces();
        integrator_.second_half(p_, table_);
      }
      ++steps_;
    }
    // Ghosts as their owners end the call (diagnostics, and a sample that computes its own
    // virial, read their velocities).
    if (slabs_) slabs_->update_ghosts(p_);
    stop_work_clock(work, steps);
    if constexpr (V::friction) {
      int overflow = 0;
      Kokkos::deep_copy(overflow, history_overflow_);
      if (comm_.any(overflow != 0))
        throw std::runtime_error("a particle had more than " +
                                 std::to_string(Store::history_slots) +
                                 " simultaneous contacts: the packing is unphysically dense "
                                 "(huge overlaps?); reduce dt or check the scene");
    }
  }

  // Whether some particle moved more than skin/2 since the last build: proved not by the
  // watch's bound when it can, else measured (neighbours/rebuild_watch.hpp). The exact
  // comparison is made in Real, so both ways rebuild at the same steps.
  bool list_expired() {
    if (!watch_.exact_known()) {
      if (watch_.bound_proves_valid()) return false;
      ++exact_checks_;
      watch_.measured(global_max(integrator_.largest_displacement2(p_)));
    }
    const Real rebuild_d2 = Real(0.25) * skin_ * skin_;  // (skin/2)^2
    return Real(watch_.exact_d2()) > rebuild_d2;
  }

  // Wraps periodic coordinates, hands particles between processes, deletes escaped ones,
  // sorts by cell and rebuilds the Verlet list; x_ref remembers where particles were, for
  // the skin criterion.
  void rebuild_lists() override {
    wrap_periodic();
    const auto grow = [this](int capacity) { Population::grow(p_, capacity); };
    if (slabs_) slabs_->migrate(p_, permutation_, grow);
    population_.remove_escaped(p_, permutation_);
    sort_.sort(grid_, p_.x, p_.id, p_.n);
    permutation_.apply(p_, sort_.order, p_.n);
    if (slabs_) {
      slabs_->append_ghosts(p_, sort_.cell_start, ghost_start_, grow);
      list_.build(grid_, box_, sort_.cell_start, p_.x, p_.species, table_.radius, skin_, p_.n,
                  GhostCells<Mem>{ghost_start_, p_.n});
    } else {
      list_.build(grid_, box_, sort_.cell_start, p_.x, p_.species, table_.radius, skin_, p_.n);
    }
    copy_prefix<ExecSpace>(p_.x_ref, p_.x, int(p_.x.extent(0)));  // space_alloc.hpp: not on OpenMP
    mark_runs_near_obstacle();
    watch_.rebuilt();
    ++builds_;
    last_build_step_ = steps_;
  }

  // Which of the fused step's work items may touch the obstacle before the next build
  // (obstacle_runs.hpp), from where the particles were at the last build (x_ref): at a
  // rebuild and when a state is imported with its list. The fused step tests only their
  // particles, and every particle of a run it does not know: the last run when it is not
  // full (particles inserted since fill it), or all of them before any marking.
  void mark_runs_near_obstacle() {
    if constexpr (V::obstacle::present) {
      using Kernel = FusedStepKernel<V, ExecSpace, Paths>;
      const int runs = Kernel::work_items(p_.n);
      if (int(near_obstacle_runs_.extent(0)) < runs)
        near_obstacle_runs_ = decltype(near_obstacle_runs_)(
            alloc_on<ExecSpace>("near_obstacle_runs"), Kernel::work_items(p_.capacity()));
      const NearObstacleRuns<Dim, Real, Obstacle, Mem> mark{
          near_obstacle_runs_, p_.x_ref,      p_.species, table_.radius,
          obstacle_,           double(skin_), p_.n,       Kernel::run_length};
      Kokkos::parallel_for("near_obstacle_runs", Policy(0, runs), mark);
      near_obstacle_runs_known_ = p_.n / Kernel::run_length;  // the full runs
    }
  }

  // The forces at the current state, and each particle's contact virial of these very
  // pair forces, for a field sample before the next step (docs/fields.md, "The contact
  // virial": damping at the velocities the forces see, v^(n+1/2) at the end of a step).
  void compute_forces() {
    Kokkos::parallel_for("contact_forces_and_virial", Policy(0, p_.n),
                         force_kernel<ForceMode::forces_and_virial>(p_, pair_loop(), p_.virial));
    virial_recorded_ = true;
  }

  // The force kernel over `from`'s particles and `pairs`' list: the one place its
  // arguments are listed (the virial view not in ForceMode::forces).
  template <ForceMode Mode = ForceMode::forces>
  ContactForceKernel<V, ExecSpace, Mode> force_kernel(
      const Store& from, const PairLoop<Dim, Real, Mem>& pairs,
      const Kokkos::View<Real * [Dim * Dim], Mem>& virial = {}) const {
    return {from, pairs, table_, obstacle_, Real(setup_.dt), history_overflow_, virial};
  }

  // Forces at the current positions, then the end of this step and the start of the next
  // in one pass; returns the largest squared speed of the drift (by_speed) or the largest
  // squared displacement since the last list build.
  Real fused_step(bool by_speed) {
    const FusedStepKernel<V, ExecSpace, Paths> kernel = fused_kernel(by_speed, false);
    Real moved2 = 0;
    Kokkos::parallel_reduce("fused_step", Policy(0, kernel.work_items(p_.n)), kernel,
                            Kokkos::Max<Real>(moved2));
    ++step_regions_;
    swap_step_buffers();
    return moved2;
  }

  // Up to max_steps fused steps, each reported by speed, in one parallel region
  // (fused_steps.hpp): as many as the host's loop would take in a row without an exact
  // check. Returns how many; the watch has seen each one's top speed.
  long fused_steps(long max_steps) {
    if constexpr (!Paths::host) {
      return 0;  // never called: steps_in_one_region() is false
    } else {
      const FusedStepsPass<V, ExecSpace, Paths> pass{
          fused_kernel(true, false),      fused_kernel(true, true), watch_.speed_bound(), max_steps,
          top_speed2_of_steps(max_steps), steps_done_in_region_};
      Kokkos::parallel_for("fused_steps", Kokkos::TeamPolicy<ExecSpace>(1, region_team_size()),
                           pass);
      ++step_regions_;
      long done = 0;
      Kokkos::deep_copy(done, steps_done_in_region_);
      const auto speeds =
          host_copy<Paths>(Kokkos::subview(top_speed2_, Kokkos::make_pair(0L, done)));
      for (long k = 0; k < done; ++k) watch_.drifted(speeds(k));
      if (done % 2 == 1) swap_step_buffers();
      return done;
    }
  }

  // The fused pass from the current buffers into the second ones, or (back) the reverse.
  FusedStepKernel<V, ExecSpace, Paths> fused_kernel(bool by_speed, bool back) {
    if (int(x_next_.extent(0)) < p_.capacity()) {
      x_next_ = decltype(x_next_)(alloc_on<ExecSpace>("x_next"), p_.capacity());
      v_next_ = decltype(v_next_)(alloc_on<ExecSpace>("v_next"), p_.capacity());
      if constexpr (V::friction)
        omega_next_ = decltype(omega_next_)(alloc_on<ExecSpace>("omega_next"), p_.capacity());
    }
    Store from = p_;
    PairLoop<Dim, Real, Mem> pairs = pair_loop();
    if (back) {
      from.x = pairs.x = x_next_;
      from.v = v_next_;
      from.omega = omega_next_;
    }
    return {force_kernel(from, pairs),
            back ? p_.x : x_next_,
            back ? p_.v : v_next_,
            back ? p_.omega : omega_next_,
            integrator_.gravity,
            by_speed,
            p_.n,
            near_obstacle_runs_,
            near_obstacle_runs_known_};
  }
  void swap_step_buffers() {
    std::swap(p_.x, x_next_);
    std::swap(p_.v, v_next_);
    if constexpr (V::friction) std::swap(p_.omega, omega_next_);
  }

  // Whether fused steps may share one region: on host paths whose team can hold all the
  // backend's threads, on one process (ghosts are exchanged between steps), for small
  // enough scenes (fused_steps.hpp), unless the setup asks to measure every step exactly.
  bool steps_in_one_region() const {
    if constexpr (!Paths::host) {
      return false;
    } else {
      return setup_.steps_per_region > 1 && !slabs_ && !setup_.exact_list_check &&
             p_.n <= step_regions_particles_per_thread * ExecSpace().concurrency() &&
             region_team_size() == ExecSpace().concurrency();
    }
  }
  int region_team_size() const {
    if (region_team_size_ == 0) {
      const FusedStepsPass<V, ExecSpace, Paths> probe{};
      region_team_size_ = std::min(
          ExecSpace().concurrency(),
          Kokkos::TeamPolicy<ExecSpace>(1, 1).team_size_max(probe, Kokkos::ParallelForTag()));
    }
    return region_team_size_;
  }
  Kokkos::View<double*, Mem> top_speed2_of_steps(long steps) {
    if (long(top_speed2_.extent(0)) < steps)
      top_speed2_ = decltype(top_speed2_)(alloc_on<ExecSpace>("top_speed2"), steps);
    return top_speed2_;
  }

  Diagnostics diagnostics() const override { return diagnostics_part().compute(comm_); }
  std::vector<std::pair<int, int>> contact_pairs() const override {
    return diagnostics_part().contact_pairs();
  }
  std::vector<SpeciesMoments> species_moments() const override {
    return diagnostics_part().species_moments(int(setup_.species.size()), comm_);
  }

  std::size_t size() const override { return std::size_t(p_.n); }
  long global_size() const override { return comm_.sum(long(p_.n)); }
  void decompose(const Decomposition& d) override {
    if (!slabs_) return;
    if (slabs_->axis() != int(d.axis)) {
      if (p_.n > 0 || builds_ > 0)
        throw std::logic_error("the slab axis is chosen before any particle is placed");
      slabs_.emplace(comm_, grid_, setup_.box, int(d.axis));
    }
    slabs_->set_balance(d.balance);
  }
  HaloStats halo_stats() const override {
    if (!slabs_) return HaloStats{};
    HaloStats h = slabs_->stats();
    h.sync_seconds = sync_seconds_;
    return h;
  }
  // Several processes: in one process's order (particles/slab_state.hpp).
  SnapshotPart snapshot_part() const override {
    if (slabs_) return slab_state::snapshot_part<Paths>(particles(), p_, grid_, *slabs_);
    SnapshotPart part;
    part.particles = particles();
    part.total = p_.n;
    if (p_.n > 0) part.rows.push_back({0, long(p_.n)});
    return part;
  }
  long steps_done() const override { return steps_; }
  long list_builds() const override { return builds_; }
  long exact_list_checks() const override { return exact_checks_; }
  long step_regions() const override { return step_regions_; }
  double skin() const override { return double(skin_); }
  double time() const override { return double(steps_) * setup_.dt; }
  // A host backend on device paths says so (docs/cuda.md, "Branch points").
  std::string variant() const override {
    const bool device_paths_on_host = !Paths::host && host_accessible<ExecSpace>();
    return V::name() + "/" + ExecSpace::name() + (device_paths_on_host ? "/device-paths" : "");
  }

  // Several processes: every rank places the same particles (population.hpp) and keeps
  // its slab's; the count returned is the whole event's, the same on every rank. New
  // particles overwrite the ghost rows, so a caller that defers the rebuild
  // (rebuild_lists = false) must rebuild before the next step, as it must anyway.
  int insert(const InsertionRequest& request) override {
    const int before = p_.n;
    const int placed = population_.insert(p_, request, slabs_ ? &comm_ : nullptr);
    if (slabs_ && placed > 0) slabs_->keep_own(p_, permutation_, before);
    if (request.count > 0 && request.rebuild_lists) rebuild_lists();
    return placed;
  }
  RemovalCounts remove_escaped() override {
    rebuild_lists();
    return removed();
  }
  // Several processes: each counts its own deletions; one sum over ranks (exact: counts).
  RemovalCounts removed() const override {
    RemovalCounts r = population_.removed();
    if (!slabs_) return r;
    std::vector<double> counts{r.low.begin(), r.low.end()};
    counts.insert(counts.end(), r.high.begin(), r.high.end());
    comm_.sum_in_place(counts);
    for (int d = 0; d < 3; ++d) {
      r.low[d] = long(counts[d]);
      r.high[d] = long(counts[3 + d]);
    }
    return r;
  }
  int next_id() const override { return population_.next_id(); }

  void configure_sampling(const FieldSampling& f) override { sampler_.configure(f); }

  // The virial of the last force pass where it recorded one at this step; otherwise (a
  // state from a checkpoint that held none) computed here, at the current velocities.
  void sample_fields(int block) override {
    if (virial_recorded_) {
      sampler_.sample(block, p_, p_.virial);
    } else {
      sampler_.sample_computing_virial(block, p_, force_kernel<ForceMode::virial>(p_, pair_loop()));
    }
  }

  std::vector<double> field_sums(bool profile) const override {
    std::vector<double> sums = sampler_.to_host(profile);
    comm_.sum_in_place(sums);
    return sums;
  }
  // The sums are global (field_sums adds over ranks): rank 0 takes them, the others zero.
  void restore_field_sums(const std::vector<double>& grid,
                          const std::vector<double>& profile) override {
    sampler_.from_host(grid, profile, !slabs_ || comm_.is_root());
  }

  // Several processes: the whole state on rank 0, the scalars on the others; the result is
  // the one-process state, bit for bit (particles/slab_state.hpp).
  SolverState export_state() const override {
    SolverState s;
    s.dim = Dim;
    s.step = steps_;
    s.next_id = population_.next_id();
    state_io::export_particles<Paths>(p_, s);
    if (!virial_recorded_) s.contact_virial.clear();  // none to hand on (sample_fields)
    s.list_builds = builds_;
    s.skin = double(skin_);
    s.last_build_step = last_build_step_;
    const RemovalCounts gone = removed();
    s.removed_low = gone.low;
    s.removed_high = gone.high;
    if (!slabs_) {
      state_io::to_host<Paths>(list_.offsets, p_.n + 1, s.neighbour_offsets);
      state_io::to_host<Paths>(list_.neighbours, list_.total, s.neighbours);
      return s;
    }
    return slab_state::gather<Dim, Real, ExecSpace, Paths>(s, p_, grid_, box_, table_.radius, skin_,
                                                           *slabs_, comm_);
  }

  // Refuses (InvalidCheckpoint, nothing changed) a state that does not fit this solver.
  void import_state(const SolverState& s) override {
    const SolverFit f = state_io::solver_fit<Dim, Real, Store::history_slots>(setup_, V::friction);
    check_state(s);  // as read_checkpoint did: the checks below rely on it
    check_fit(s, f);
    const Real skin = state_skin(s);
    state_io::check_lists<Dim, Real, ExecSpace, Paths>(s, grid_, box_, population_.escape_test(),
                                                       table_.radius, skin);
    check_contacts(s, f);
    const RemovalCounts gone{s.removed_low, s.removed_high};
    steps_ = s.step;
    builds_ = s.list_builds;
    last_build_step_ = s.last_build_step;
    virial_recorded_ = !s.contact_virial.empty();
    use_skin(double(skin));
    if (slabs_) {
      import_own_part(s);
      population_.restore(s.next_id, comm_.is_root() ? gone : RemovalCounts{});
    } else {
      if (int(s.size()) > p_.capacity()) p_.allocate(int(s.size()) + int(s.size()) / 4);
      state_io::import_particles<Paths>(p_, s);
      list_.assign(s.neighbour_offsets, s.neighbours);
      population_.restore(s.next_id, gone);
    }
    mark_runs_near_obstacle();  // not the marks of the particles this solver held before
  }

  // Several processes, from the whole state: the particles whose reference position is in
  // this slab (where the last rebuild left them), the ghosts and the list as that rebuild
  // made them (from reference positions), then the ghosts' current motion. Public because
  // it launches kernels (nvcc).
  void import_own_part(const SolverState& s) {
    const SolverState own = slab_state::own_part<Dim, Position>(s, *slabs_);
    if (int(own.size()) > p_.capacity()) p_.allocate(int(own.size()) + int(own.size()) / 4);
    state_io::import_particles<Paths>(p_, own);
    const auto grow = [this](int capacity) { Population::grow(p_, capacity); };
    std::swap(p_.x, p_.x_ref);  // the rebuild's positions, for ghosts, cells and the list
    sort_.sort(grid_, p_.x, p_.id, p_.n);
    slabs_->append_ghosts(p_, sort_.cell_start, ghost_start_, grow);
    list_.build(grid_, box_, sort_.cell_start, p_.x, p_.species, table_.radius, skin_, p_.n,
                GhostCells<Mem>{ghost_start_, p_.n});
    std::swap(p_.x, p_.x_ref);
    slabs_->update_ghosts(p_);
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

 private:
  // Several processes: this rank's compute time in advance() (halo and waits excluded),
  // for the balance by work.
  struct WorkClock {
    std::chrono::steady_clock::time_point start;
    double halo = 0, sync = 0;
  };
  WorkClock start_work_clock() const {
    if (!slabs_) return {};
    return {std::chrono::steady_clock::now(), slabs_->stats().exchange_seconds(), sync_seconds_};
  }
  void stop_work_clock(const WorkClock& c, long steps) {
    if (!slabs_) return;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - c.start).count();
    const double waits = (slabs_->stats().exchange_seconds() - c.halo) + (sync_seconds_ - c.sync);
    slabs_->account_work(std::max(0.0, wall - waits), double(p_.n) * double(steps));
  }

  // The largest displacement over every process (timed on several: halo_stats).
  double global_max(Real local) {
    if (!slabs_) return double(local);
    const auto start = std::chrono::steady_clock::now();
    const double largest = comm_.max(double(local));
    sync_seconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return largest;
  }

  // Adaptive skin, before a build that a displacement forced: the skin of least modelled
  // cost (core/skin_model.hpp) from the interval that ends here. Counts are summed over
  // processes and the displacement is the global one, so every rank picks the same skin.
  void choose_skin() {
    const long steps = steps_ - last_build_step_;
    const long particles = comm_.sum(long(p_.n)), entries = comm_.sum(long(list_.total));
    if (steps <= 0 || particles <= 0) return;
    const SkinSample interval{double(skin_), double(entries) / double(particles),
                              std::sqrt(watch_.exact_d2()) / double(steps)};
    use_skin(skin_model_.best(interval));
  }
  void use_skin(double skin) {
    skin_ = Real(skin);
    watch_ = RebuildWatch(0.5 * double(skin_), double(Real(setup_.dt)));
  }

  // The skin a state's list was built with: the scene's unless the skin adapts (files
  // from before the adaptive skin store 0, the scene's).
  Real state_skin(const SolverState& s) const {
    if (s.skin == 0 || Real(s.skin) == Real(setup_.skin())) return Real(setup_.skin());
    if (!setup_.adaptive_skin)
      throw InvalidCheckpoint(
          fmt::format("/state@skin = {} m, but the scene's skin is {} m and does not adapt", s.skin,
                      setup_.skin()));
    // Compared in Real: a single-precision solver stores its float skin, which may round
    // below the double bounds.
    const Real skin = Real(s.skin);
    if (!(skin >= Real(setup_.smallest_adaptive_skin()) && skin <= Real(setup_.skin())))
      throw InvalidCheckpoint(
          fmt::format("/state@skin = {} m is not in the adaptive range [{}, {}] m", s.skin,
                      setup_.smallest_adaptive_skin(), setup_.skin()));
    return skin;
  }

  static const SolverSetup& validated(const SolverSetup& s) {
    if (s.species.empty()) throw UserError("a scene needs at least one species");
    if (!(s.max_diameter() > 0)) throw UserError("particle diameters must be > 0");
    if (!V::matches(s)) throw std::logic_error("DemSolver variant does not match the scene");
    return s;
  }

  PairLoop<Dim, Real, Mem> pair_loop() const {
    return {list_.offsets, list_.neighbours, p_.x, p_.species, table_.radius, box_, max_radius()};
  }
  // Not smaller than any species' radius in the table (the same double, then rounded).
  Real max_radius() const { return Real(0.5 * setup_.max_diameter()); }
  SolverDiagnostics<V, ExecSpace, Paths> diagnostics_part() const {
    return {p_, pair_loop(), table_, obstacle_};
  }

  SolverSetup setup_;
  const Communicator& comm_;
  PairTable<Model, Real, Mem> table_;
  BoxGeometry<Dim, Position> box_;
  Obstacle obstacle_;
  Real skin_;
  CellGrid<Dim, Position> grid_;
  VelocityVerlet<V, ExecSpace> integrator_;

  Store p_;
  Population population_;
  ParticlePermutation<ExecSpace, Store> permutation_;
  std::optional<SlabExchange<Dim, Store, ExecSpace, Paths>> slabs_;  // several processes only
  Kokkos::View<int*, Mem> ghost_start_;                              // their ghosts' cells
  CellSort<Dim, Position, ExecSpace> sort_;
  VerletList<Dim, Real, ExecSpace, Paths> list_;
  Kokkos::View<int, Mem> history_overflow_;

  FieldSampler<V, ExecSpace, Paths> sampler_;
  Kokkos::View<double*, Mem> top_speed2_;  // fused_steps: each step's top speed^2
  Kokkos::View<long, Mem> steps_done_in_region_{"steps_done_in_region"};
  mutable int region_team_size_ = 0;
  typename Store::PositionView x_next_;  // the fused step's second buffers
  typename Store::VectorView v_next_;
  typename Store::ScalarView omega_next_;
  Kokkos::View<std::uint8_t*, Mem> near_obstacle_runs_;  // obstacle scenes only
  int near_obstacle_runs_known_ = 0;                     // work items marked at the build
  long steps_ = 0;
  long builds_ = 0;
  RebuildWatch watch_;
  SkinModel skin_model_;      // adaptive skin only
  long last_build_step_ = 0;  // steps_ at the last list build
  long exact_checks_ = 0;     // exact displacement passes after a bound that failed
  long step_regions_ = 0;
  double sync_seconds_ = 0;
  // Whether p_.virial is the contact virial of the force pass that ended the current step
  // (compute_forces; or a state's that was: import_state), 0 for particles inserted since.
  bool virial_recorded_ = false;
};

}  // namespace granshock

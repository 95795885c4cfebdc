// The time loop of a DemSolver (docs/design.md, "The solver"): velocity Verlet with the
// second half of one step, the forces and the first half of the next fused into one pass
// (fused_step.hpp), several such steps in one parallel region where the host may
// (fused_steps.hpp), and the lists rebuilt when list_keeping.hpp says they expired.
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "kernels/device/host_mirror.hpp"
#include "kernels/device/space_alloc.hpp"
#include "kernels/solver/chained_steps.hpp"
#include "kernels/solver/contact_forces.hpp"
#include "kernels/solver/fused_step.hpp"
#include "kernels/solver/fused_steps.hpp"
#include "kernels/solver/list_keeping.hpp"
#include "kernels/solver/solver_parts.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths>
class StepLoop {
 public:
  using Parts = SolverParts<V, ExecSpace, Paths>;
  using Real = typename Parts::Real;
  using Mem = typename Parts::Mem;
  using Store = typename Parts::Store;
  using Policy = typename Parts::Types::Policy;
  static constexpr int Dim = Parts::Dim;

  StepLoop(Parts& parts, ListKeeping<V, ExecSpace, Paths>& lists) : s_(parts), lists_(lists) {}

  // Velocity Verlet, steps times. Inside the loop the second half of step n, the first
  // half of n+1 and the forces between them are one fused pass (fused_step.hpp); the
  // first step starts with the first half and the last ends with forces and the second
  // half, so between calls x, v and f belong to the same step, as with separate halves.
  // That last pass (close_step) also records each particle's contact virial, which a
  // field sample at this step reads.
  void advance(long steps) {
    if (steps <= 0) return;
    if (steps > 1 && steps_chained_on_device()) {  // one step: nothing to chain
      advance_chained(steps);
      check_history_overflow();
      return;
    }
    const WorkClock work = start_work_clock();
    s_.watch.measured(s_.global_max(s_.integrator.first_half(s_.p, s_.table)));
    for (long k = 0; k < steps; ++k) {
      if (!rebuild_if_expired() && s_.slabs) s_.slabs->update_ghosts(s_.p);
      if (k + 1 < steps) {
        const bool by_speed = next_drift_by_speed();
        if (by_speed && steps_in_one_region()) {
          const long done = fused_steps(std::min(steps - 1 - k, s_.setup.steps_per_region));
          k += done - 1;  // the loop counts the last
          s_.steps += done - 1;
        } else {
          const double reported = s_.global_max(fused_step(by_speed));
          if (by_speed) {
            s_.watch.drifted(reported);
          } else {
            s_.watch.measured(reported);
          }
        }
      } else {
        close_step();
      }
      ++s_.steps;
    }
    // Ghosts as their owners end the call (diagnostics, and a sample that computes its own
    // virial, read their velocities).
    if (s_.slabs) s_.slabs->update_ghosts(s_.p);
    stop_work_clock(work, steps);
    check_history_overflow();
  }

  // advance() on device paths and one process (chained_steps.hpp): the same steps, the
  // rebuild decision kept on the device between the host's turns. The host reads the
  // chain's state once per chain, and acts where the host loop would (a list build, an
  // exact displacement pass) before queueing the next.
  void advance_chained(long steps) {
    write_chain_state(false);
    long counted = 0;  // the steps of the state's count already taken into account
    s_.integrator.first_half("verlet::first_half->device", s_.p, s_.table,
                             Kokkos::Max<Real, Mem>(s_.chain_reported));
    launch_chain_watch(false);
    long k = 0;
    while (k + 1 < steps) {
      const long queued = chain_length(steps - 1 - k);
      // Forth from the current buffers into the second ones, then back (no swap until the
      // chain is read).
      const ChainedFusedStep<V, ExecSpace, Paths> forth{fused_kernel(false, false), s_.chain_state},
          back{fused_kernel(false, true), s_.chain_state};
      const Policy items(0, forth.kernel.work_items(s_.p.n));
      for (long j = 0; j < queued; ++j) {
        Kokkos::parallel_reduce("fused_step->device", items, j % 2 == 0 ? forth : back,
                                Kokkos::Max<Real, Mem>(s_.chain_reported));
        launch_chain_watch(true);
      }
      ChainState read;
      Kokkos::deep_copy(read, s_.chain_state);  // the chain's one read
      const long taken = read.done - counted;
      counted = read.done;
      s_.watch = read.watch;
      k += taken;
      s_.steps += taken;
      s_.step_regions += taken;
      if (taken % 2 == 1) swap_step_buffers();
      if (!read.stopped && taken != queued)
        throw std::logic_error("a chain neither ran its steps nor stopped");
      if (read.stopped && k + 1 < steps) {
        rebuild_if_expired();  // as the host loop, which would check here
        write_chain_state(next_drift_by_speed());
        counted = 0;
      }
    }
    rebuild_if_expired();
    close_step();
    ++s_.steps;
  }

  // The forces, each particle's contact virial and the second half of the step that ends
  // a call of advance(), in one pass (fused_step.hpp, Closing): the arithmetic of
  // compute_forces() and of a separate second half kick, operation for operation, so the
  // trajectory is bitwise that of the two kernels it replaced, without a pass over every
  // particle's list that forms the periodic image everywhere, and a launch fewer.
  void close_step() {
    auto& p = s_.p;
    ensure_step_buffers();
    const auto kernel =
        step_kernel<true>(force_kernel<ForceMode::forces_and_virial>(p, s_.pair_loop(), p.virial),
                          {}, s_.v_next, s_.omega_next, false);
    Kokkos::parallel_for("closing_step", Policy(0, kernel.work_items(p.n)), kernel);
    std::swap(p.v, s_.v_next);
    if constexpr (V::friction) std::swap(p.omega, s_.omega_next);
    s_.virial_recorded = true;
  }

  // The forces at the current state, and each particle's contact virial of these very
  // pair forces, for a field sample before the next step (docs/fields.md, "The contact
  // virial": damping at the velocities the forces see, v^(n+1/2) at the end of a step).
  void compute_forces() {
    Kokkos::parallel_for(
        "contact_forces_and_virial", Policy(0, s_.p.n),
        force_kernel<ForceMode::forces_and_virial>(s_.p, s_.pair_loop(), s_.p.virial));
    s_.virial_recorded = true;
  }

  // The force kernel over `from`'s particles and `pairs`' list: the one place its
  // arguments are listed (the virial view not in ForceMode::forces).
  template <ForceMode Mode = ForceMode::forces>
  ContactForceKernel<V, ExecSpace, Mode> force_kernel(
      const Store& from, const PairLoop<Dim, Real, Mem>& pairs,
      const Kokkos::View<Real * [Dim * Dim], Mem>& virial = {}) const {
    return {from,   pairs,   s_.table, s_.obstacle, Real(s_.setup.dt), s_.history_overflow,
            virial, s_.walls};
  }

  // Forces at the current positions, then the end of this step and the start of the next
  // in one pass; returns the largest squared speed of the drift (by_speed) or the largest
  // squared displacement since the last list build.
  Real fused_step(bool by_speed) {
    const FusedStepKernel<V, ExecSpace, Paths> kernel = fused_kernel(by_speed, false);
    Real moved2 = 0;
    Kokkos::parallel_reduce("fused_step", Policy(0, kernel.work_items(s_.p.n)), kernel,
                            Kokkos::Max<Real>(moved2));
    ++s_.step_regions;
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
      const int team = region_team_size();
      using Pass = FusedStepsPass<V, ExecSpace, Paths>;
      const Pass pass{fused_kernel(true, false),
                      fused_kernel(true, true),
                      s_.watch.speed_bound(),
                      max_steps,
                      top_speed2_of_steps(max_steps),
                      s_.steps_done_in_region,
                      s_.thread_shares.cuts(Pass::Kernel::work_items(s_.p.n), team),
                      s_.thread_shares.seconds()};
      Kokkos::parallel_for("fused_steps", Kokkos::TeamPolicy<ExecSpace>(1, team), pass);
      ++s_.step_regions;
      long done = 0;
      Kokkos::deep_copy(done, s_.steps_done_in_region);
      s_.thread_shares.balance(done);
      const auto speeds =
          host_copy<Paths>(Kokkos::subview(s_.top_speed2, Kokkos::make_pair(0L, done)));
      for (long k = 0; k < done; ++k) s_.watch.drifted(speeds(k));
      if (done % 2 == 1) swap_step_buffers();
      return done;
    }
  }

  // The fused pass from the current buffers into the second ones, or (back) the reverse.
  FusedStepKernel<V, ExecSpace, Paths> fused_kernel(bool by_speed, bool back) {
    auto& p = s_.p;
    ensure_step_buffers();
    Store from = p;
    PairLoop<Dim, Real, Mem> pairs = s_.pair_loop();
    if (back) {
      from.x = pairs.x = s_.x_next;
      from.v = s_.v_next;
      from.omega = s_.omega_next;
    }
    return step_kernel(force_kernel(from, pairs), back ? p.x : s_.x_next, back ? p.v : s_.v_next,
                       back ? p.omega : s_.omega_next, by_speed);
  }

  // A fused (or, Closing, the closing) pass with these forces, writing into these buffers,
  // with the solver's gravity and the work items' marks.
  template <bool Closing = false, class Forces>
  FusedStepKernel<V, ExecSpace, Paths, Closing> step_kernel(
      const Forces& forces, const typename Store::PositionView& x_next,
      const typename Store::VectorView& v_next, const typename Store::SpinView& omega_next,
      bool by_speed) const {
    return {forces,   x_next, v_next,       omega_next,         s_.integrator.gravity,
            by_speed, s_.p.n, s_.run_marks, s_.run_marks_known, s_.image_spans};
  }

 private:
  // The list check before each step: a rebuild (after the adaptive skin's choice) when
  // some particle may have moved more than skin/2. True when it rebuilt.
  bool rebuild_if_expired() {
    if (!lists_.expired()) return false;
    if (s_.setup.adaptive_skin) lists_.choose_skin();
    lists_.rebuild();
    return true;
  }

  // Whether the next step reports its top speed (the watch's bound) rather than the exact
  // displacement (ChainWatch asks the same on the device).
  bool next_drift_by_speed() const {
    return !s_.setup.exact_list_check && s_.watch.next_drift_by_speed();
  }

  void check_history_overflow() {
    if constexpr (V::friction) {
      int overflow = 0;
      Kokkos::deep_copy(overflow, s_.history_overflow);
      if (s_.comm.any(overflow != 0))
        throw std::runtime_error("a particle had more than " +
                                 std::to_string(Store::history_slots) +
                                 " simultaneous contacts: the packing is unphysically dense "
                                 "(huge overlaps?); reduce dt or check the scene");
    }
  }

  // Device paths on one process chain their steps (several processes exchange ghosts and
  // agree on the displacement between steps, on the host).
  bool steps_chained_on_device() const { return !Paths::host && !s_.slabs; }

  // How many steps to queue: the steps left before the call's last, at most
  // steps_per_region, and, once two builds are known, about as many as remain of the last
  // build interval (at least chain_floor): steps queued past a list build do nothing, but
  // each costs two launches.
  static constexpr long chain_floor = 16;
  long chain_length(long left) const {
    long n = std::min(left, std::max(1L, s_.setup.steps_per_region));
    if (s_.last_build_interval > 0) {
      const long since = s_.steps - s_.last_build_step;
      n = std::min(n, std::max(chain_floor, s_.last_build_interval - since));
    }
    return n;
  }

  // The host's watch onto the device, the count from 0, and the next step's report: a
  // one-thread kernel, queued like the steps (a deep_copy of a value fences).
  void write_chain_state(bool by_speed) {
    ChainState c;
    c.watch = s_.watch;
    c.by_speed = by_speed ? 1 : 0;
    Kokkos::parallel_for("chain_state", Policy(0, 1), SetChainState<Mem>{s_.chain_state, c});
  }
  void launch_chain_watch(bool after_step) {
    const ChainWatch<Real, Mem> watch{s_.chain_state, s_.chain_reported, lists_.rebuild_distance2(),
                                      s_.setup.exact_list_check, after_step};
    Kokkos::parallel_for("chain_watch", Policy(0, 1), watch);
  }

  // The second buffers the fused passes write, as large as the particle store.
  void ensure_step_buffers() {
    auto& p = s_.p;
    if (int(s_.x_next.extent(0)) >= p.capacity()) return;
    s_.x_next = decltype(s_.x_next)(alloc_on<ExecSpace>("x_next"), p.capacity());
    s_.v_next = decltype(s_.v_next)(alloc_on<ExecSpace>("v_next"), p.capacity());
    if constexpr (V::friction)
      s_.omega_next = decltype(s_.omega_next)(alloc_on<ExecSpace>("omega_next"), p.capacity());
  }

  void swap_step_buffers() {
    std::swap(s_.p.x, s_.x_next);
    std::swap(s_.p.v, s_.v_next);
    if constexpr (V::friction) std::swap(s_.p.omega, s_.omega_next);
  }

  // Whether fused steps may share one region: on host paths whose team can hold all the
  // backend's threads, on one process (ghosts are exchanged between steps), for small
  // enough scenes (fused_steps.hpp), unless the setup asks to measure every step exactly.
  bool steps_in_one_region() {
    if constexpr (!Paths::host) {
      return false;
    } else {
      return s_.setup.steps_per_region > 1 && !s_.slabs && !s_.setup.exact_list_check &&
             s_.p.n <= step_regions_particles_per_thread * ExecSpace().concurrency() &&
             region_team_size() == ExecSpace().concurrency();
    }
  }
  int region_team_size() {
    if (s_.region_team_size == 0) {
      const FusedStepsPass<V, ExecSpace, Paths> probe{};
      s_.region_team_size = std::min(
          ExecSpace().concurrency(),
          Kokkos::TeamPolicy<ExecSpace>(1, 1).team_size_max(probe, Kokkos::ParallelForTag()));
    }
    return s_.region_team_size;
  }
  Kokkos::View<double*, Mem> top_speed2_of_steps(long steps) {
    if (long(s_.top_speed2.extent(0)) < steps)
      s_.top_speed2 = decltype(s_.top_speed2)(alloc_on<ExecSpace>("top_speed2"), steps);
    return s_.top_speed2;
  }

  // Several processes: this rank's compute time in advance() (halo and waits excluded),
  // for the balance by work.
  struct WorkClock {
    std::chrono::steady_clock::time_point start;
    double halo = 0, sync = 0;
  };
  WorkClock start_work_clock() const {
    if (!s_.slabs) return {};
    return {std::chrono::steady_clock::now(), s_.slabs->stats().exchange_seconds(),
            s_.sync_seconds};
  }
  void stop_work_clock(const WorkClock& c, long steps) {
    if (!s_.slabs) return;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - c.start).count();
    const double waits =
        (s_.slabs->stats().exchange_seconds() - c.halo) + (s_.sync_seconds - c.sync);
    s_.slabs->account_work(std::max(0.0, wall - waits), double(s_.p.n) * double(steps));
  }

  Parts& s_;
  ListKeeping<V, ExecSpace, Paths>& lists_;
};

}  // namespace granshock

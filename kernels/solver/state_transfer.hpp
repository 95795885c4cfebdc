// A DemSolver's particles and state to and from the host (docs/output_format.md): given
// particles, snapshots, and the whole state of a checkpoint out and back in, refused
// before anything changes when it does not fit (core/checkpoint_checks.hpp). The array
// copies and the solver's own checks of a state are in state_io.hpp; several processes'
// gathering and splitting in particles/slab_state.hpp.
#pragma once

#include <fmt/format.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <string>
#include <utility>

#include "core/checkpoint_checks.hpp"
#include "core/host_particles.hpp"
#include "core/snapshot_part.hpp"
#include "core/solver_state.hpp"
#include "core/user_error.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/particles/slab_state.hpp"
#include "kernels/solver/list_keeping.hpp"
#include "kernels/solver/solver_parts.hpp"
#include "kernels/solver/state_io.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths>
class StateTransfer {
 public:
  using Parts = SolverParts<V, ExecSpace, Paths>;
  using Real = typename Parts::Real;
  using Mem = typename Parts::Mem;
  using Store = typename Parts::Store;
  using Position = typename Parts::Position;
  static constexpr int Dim = Parts::Dim;

  StateTransfer(Parts& parts, ListKeeping<V, ExecSpace, Paths>& lists) : s_(parts), lists_(lists) {}

  // Several processes: each keeps the particles of its slab (every rank is given all).
  // The caller rebuilds the lists and computes the forces.
  void set_particles(const HostParticles& given) {
    const HostParticles hp = s_.slabs ? slab_state::mine<Position>(given, *s_.slabs) : given;
    int next_id = 0;
    for (const int id : given.id) next_id = std::max(next_id, id + 1);
    const int n = int(hp.size());
    for (std::size_t i = 0; i < hp.size(); ++i)
      if (hp.species[i] < 0 || hp.species[i] >= int(s_.setup.species.size()))
        throw UserError("particle " + std::to_string(hp.id[i]) + " has unknown species " +
                        std::to_string(hp.species[i]));
    if (n > s_.p.capacity()) s_.p.allocate(n + n / 4);
    state_io::import_given<Paths, Store, Dim>(s_.p, hp);
    s_.population.restore(next_id, s_.population.removed());
  }

  HostParticles particles() const {
    const auto& p = s_.p;
    auto x = host_copy<Paths>(p.x);
    auto v = host_copy<Paths>(p.v);
    auto species = host_copy<Paths>(p.species);
    auto id = host_copy<Paths>(p.id);
    auto omega = host_copy<Paths>(p.omega);
    HostParticles hp;
    for (int i = 0; i < p.n; ++i) {
      std::array<double, 3> xi{0, 0, 0}, vi{0, 0, 0};
      for (int d = 0; d < Dim; ++d) {
        xi[d] = x(i, d);
        vi[d] = v(i, d);
      }
      hp.add(xi, vi, species(i), id(i));
      if constexpr (V::friction && Dim == 2) {
        hp.angular_velocity.push_back(omega(i));
      } else if constexpr (V::friction) {
        for (int c = 0; c < spin_components(Dim); ++c) hp.angular_velocity.push_back(omega(i, c));
      }
    }
    return hp;
  }

  // Several processes: in one process's order (particles/slab_state.hpp).
  SnapshotPart snapshot_part() const {
    if (s_.slabs) return slab_state::snapshot_part<Paths>(particles(), s_.p, s_.grid, *s_.slabs);
    SnapshotPart part;
    part.particles = particles();
    part.total = s_.p.n;
    if (s_.p.n > 0) part.rows.push_back({0, long(s_.p.n)});
    return part;
  }

  // Several processes: the whole state on rank 0, the scalars on the others; the result is
  // the one-process state, bit for bit (particles/slab_state.hpp). `removed` is the
  // deletions over every process.
  SolverState export_state(const RemovalCounts& removed) const {
    SolverState st;
    st.dim = Dim;
    st.step = s_.steps;
    st.next_id = s_.population.next_id();
    state_io::export_particles<Paths>(s_.p, st);
    if (!s_.virial_recorded) st.contact_virial.clear();  // none to hand on (sample_fields)
    st.list_builds = s_.builds;
    st.skin = double(s_.skin);
    st.last_build_step = s_.last_build_step;
    st.removed_low = removed.low;
    st.removed_high = removed.high;
    if (!s_.slabs) {
      state_io::to_host<Paths>(s_.list.offsets, s_.p.n + 1, st.neighbour_offsets);
      state_io::to_host<Paths>(s_.list.neighbours, s_.list.total, st.neighbours);
      return st;
    }
    return slab_state::gather<Dim, Real, ExecSpace, Paths>(
        st, s_.p, s_.grid, s_.box, s_.table.radius, s_.skin, *s_.slabs, s_.comm);
  }

  // Refuses (InvalidCheckpoint, nothing changed) a state that does not fit this solver.
  void import_state(const SolverState& st) {
    const SolverFit f =
        state_io::solver_fit<Dim, Real, Store::history_slots>(s_.setup, V::friction);
    check_state(st);  // as read_checkpoint did: the checks below rely on it
    check_fit(st, f);
    const Real skin = state_skin(st);
    state_io::check_lists<Dim, Real, ExecSpace, Paths>(
        st, s_.grid, s_.box, s_.population.escape_test(), s_.table.radius, skin);
    check_contacts(st, f);
    const RemovalCounts gone{st.removed_low, st.removed_high};
    s_.steps = st.step;
    s_.builds = st.list_builds;
    s_.last_build_step = st.last_build_step;
    s_.virial_recorded = !st.contact_virial.empty();
    lists_.use_skin(double(skin));
    if (s_.slabs) {
      import_own_part(st);
      s_.population.restore(st.next_id, s_.comm.is_root() ? gone : RemovalCounts{});
    } else {
      if (int(st.size()) > s_.p.capacity()) s_.p.allocate(int(st.size()) + int(st.size()) / 4);
      state_io::import_particles<Paths>(s_.p, st);
      s_.list.assign(st.neighbour_offsets, st.neighbours);
      s_.population.restore(st.next_id, gone);
    }
    lists_.mark_runs();  // not the marks of the particles held before
  }

  // Several processes, from the whole state: the particles whose reference position is in
  // this slab (where the last rebuild left them), the ghosts and the list as that rebuild
  // made them (from reference positions), then the ghosts' current motion. Public because
  // it launches kernels (nvcc).
  void import_own_part(const SolverState& st) {
    auto& p = s_.p;
    const SolverState own = slab_state::own_part<Dim, Position>(st, *s_.slabs);
    if (int(own.size()) > p.capacity()) p.allocate(int(own.size()) + int(own.size()) / 4);
    state_io::import_particles<Paths>(p, own);
    std::swap(p.x, p.x_ref);  // the rebuild's positions, for ghosts, cells and the list
    s_.sort.sort(s_.grid, p.x, p.id, p.n);
    s_.slabs->append_ghosts(p, s_.sort.cell_start, s_.ghost_start, lists_.grower());
    s_.list.build(s_.grid, s_.box, s_.sort.cell_start, p.x, p.species, s_.table.radius, s_.skin,
                  p.n, GhostCells<Mem>{s_.ghost_start, p.n});
    std::swap(p.x, p.x_ref);
    s_.slabs->update_ghosts(p);
  }

 private:
  // The skin a state's list was built with: the scene's unless the skin adapts (format-3
  // checkpoints written before the adaptive skin read as 0, the scene's).
  Real state_skin(const SolverState& st) const {
    const auto& setup = s_.setup;
    if (st.skin == 0 || Real(st.skin) == Real(setup.skin())) return Real(setup.skin());
    if (!setup.adaptive_skin)
      throw InvalidCheckpoint(
          fmt::format("/state@skin = {} m, but the scene's skin is {} m and does not adapt",
                      st.skin, setup.skin()));
    // Compared in Real: a single-precision solver stores its float skin, which may round
    // below the double bounds.
    const Real skin = Real(st.skin);
    if (!(skin >= Real(setup.smallest_adaptive_skin()) && skin <= Real(setup.skin())))
      throw InvalidCheckpoint(
          fmt::format("/state@skin = {} m is not in the adaptive range [{}, {}] m", st.skin,
                      setup.smallest_adaptive_skin(), setup.skin()));
    return skin;
  }

  Parts& s_;
  ListKeeping<V, ExecSpace, Paths>& lists_;
};

}  // namespace granshock

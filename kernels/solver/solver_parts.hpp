// What one DemSolver holds (kernels/solver/dem_solver.hpp): the scene's fixed geometry and
// pair table, the particles, the cell sort and Verlet list, the step loop's buffers and
// counters, and the field sampler. The parts that act on it live in their own files:
// list_keeping.hpp (when and how the lists are rebuilt), step_loop.hpp (the time loop),
// state_transfer.hpp (checkpoint states in and out). Members are declared in the order
// they are built.
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include "core/communicator.hpp"
#include "core/skin_model.hpp"
#include "core/solver_setup.hpp"
#include "core/user_error.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/device/box_geometry.hpp"
#include "kernels/models/z_walls.hpp"
#include "kernels/neighbours/cell_grid.hpp"
#include "kernels/neighbours/cell_sort.hpp"
#include "kernels/neighbours/pair_loop.hpp"
#include "kernels/neighbours/rebuild_watch.hpp"
#include "kernels/neighbours/verlet_list.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/population.hpp"
#include "kernels/particles/slab_exchange.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/sampling/field_sampler.hpp"
#include "kernels/solver/chained_steps.hpp"
#include "kernels/solver/diagnostics.hpp"
#include "kernels/solver/pair_table.hpp"
#include "kernels/solver/thread_shares.hpp"
#include "kernels/solver/velocity_verlet.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths>
struct SolverParts {
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Mem = typename Types::Mem;
  using Store = typename Types::Store;
  using Obstacle = typename Types::Obstacle;
  using Position = typename Types::Position;
  using Table = PairTable<typename Types::Model, Real, Mem>;
  using Population = ParticlePopulation<V, ExecSpace, Paths>;

  SolverParts(const SolverSetup& given, std::size_t capacity, const Communicator& c)
      : setup(validated(given)),
        comm(c),
        table(Table::template build<Paths>(setup)),
        box(BoxGeometry<Dim, Position>::from(setup.box)),
        obstacle(Obstacle::from(setup.obstacle)),
        walls(ZWalls::from(setup)),
        skin(Real(setup.skin())),
        grid(CellGrid<Dim, Position>::make(setup.box, setup.max_diameter() + setup.skin())),
        population(setup, box, obstacle),
        history_overflow("history_overflow"),
        watch(0.5 * double(skin), double(Real(setup.dt))),
        skin_model{Dim, setup.max_diameter(), grid.mean_cell_size(), setup.smallest_adaptive_skin(),
                   setup.skin()} {
    integrator.dt = Real(setup.dt);
    for (int d = 0; d < Dim; ++d) integrator.gravity[d] = Real(setup.gravity[d]);
    p.allocate(int(std::max<std::size_t>(capacity, 1)));
    list.visit_once = setup.list_visits_once;
    if (comm.size() > 1) slabs.emplace(comm, grid, setup.box, int(Decomposition{}.axis));
  }
  SolverParts(const SolverParts&) = delete;
  SolverParts& operator=(const SolverParts&) = delete;

  // The pair loop over the current list and positions.
  PairLoop<Dim, Real, Mem> pair_loop() const {
    return {list.offsets, list.neighbours, p.x, p.species, table.radius, box, max_radius()};
  }
  // Not smaller than any species' radius in the table (the same double, then rounded).
  Real max_radius() const { return Real(0.5 * setup.max_diameter()); }

  SolverDiagnostics<V, ExecSpace, Paths> diagnostics() const {
    return {p, pair_loop(), table, obstacle};
  }

  // A largest displacement or speed over every process (timed on several: halo_stats).
  double global_max(Real local) {
    if (!slabs) return double(local);
    const auto start = std::chrono::steady_clock::now();
    const double largest = comm.max(double(local));
    sync_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return largest;
  }

  // Fixed by the scene.
  SolverSetup setup;
  const Communicator& comm;
  Table table;
  BoxGeometry<Dim, Position> box;
  Obstacle obstacle;
  ZWalls walls;  // a 3-D slab's (models/z_walls.hpp)
  Real skin;     // of the current list: the scene's, or the adaptive skin's last choice
  CellGrid<Dim, Position> grid;
  VelocityVerlet<V, ExecSpace> integrator;

  // The particles, their order and, on several processes, the slabs and their ghosts.
  Store p;
  Population population;
  ParticlePermutation<ExecSpace, Store> permutation;
  std::optional<SlabExchange<Dim, Store, ExecSpace, Paths>> slabs;  // several processes only
  Kokkos::View<int*, Mem> ghost_start;                              // their ghosts' cells
  CellSort<Dim, Position, ExecSpace> sort;
  VerletList<Dim, Real, ExecSpace, Paths> list;
  Kokkos::View<int, Mem> history_overflow;

  FieldSampler<V, ExecSpace, Paths> sampler;

  // The step loop's buffers (step_loop.hpp).
  Kokkos::View<double*, Mem> top_speed2;  // fused_steps: each step's top speed^2
  Kokkos::View<long, Mem> steps_done_in_region{"steps_done_in_region"};
  int region_team_size = 0;
  ThreadShares<Mem> thread_shares{setup.thread_shares};  // the threads' runs in those regions
  typename Store::PositionView x_next;                   // the fused step's second buffers
  typename Store::VectorView v_next;
  typename Store::SpinView omega_next;
  Kokkos::View<std::uint8_t*, Mem> run_marks;  // the fused step's work items (run_marks.hpp)
  int run_marks_known = 0;                     // work items marked at the build
  Kokkos::View<int* [2], Mem> image_spans;     // per work item, host paths (run_marks.hpp)
  Kokkos::View<ChainState, Mem> chain_state{"chain_state"};  // device paths (chained_steps.hpp)
  Kokkos::View<Real, Mem> chain_reported{"chain_reported"};  // the last pass's reduction

  // Counters and the rebuild decision.
  long steps = 0;
  long builds = 0;
  RebuildWatch watch;
  SkinModel skin_model;          // adaptive skin only
  long last_build_step = 0;      // steps at the last list build
  long last_build_interval = 0;  // steps between the last two builds (0: not yet two)
  long exact_checks = 0;         // exact displacement passes after a bound that failed
  long step_regions = 0;
  double sync_seconds = 0;
  // Whether p.virial is the contact virial of the force pass that ended the current step
  // (StepLoop::close_step or compute_forces; or a state's that was: import_state), 0 for
  // particles inserted since.
  bool virial_recorded = false;

 private:
  static const SolverSetup& validated(const SolverSetup& s) {
    if (s.species.empty()) throw UserError("a scene needs at least one species");
    if (!(s.max_diameter() > 0)) throw UserError("particle diameters must be > 0");
    if (!V::matches(s)) throw std::logic_error("DemSolver variant does not match the scene");
    if (s.z_walls && (Dim != 3 || s.box.periodic[2]))
      throw UserError("walls across z need a 3-D scene with an open z axis");
    return s;
  }
};

}  // namespace granshock

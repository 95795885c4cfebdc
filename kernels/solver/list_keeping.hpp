// Keeping the neighbour lists of a DemSolver (docs/design.md, "The solver"): whether some
// particle has moved more than skin/2 since the last build, the rebuild itself (periodic
// wrap, migration between processes, deletion at open boundaries, the cell sort, the
// Verlet list), the marks of the fused step's work items (run_marks.hpp), and the adaptive
// skin's choice before a rebuild.
#pragma once

#include <Kokkos_Core.hpp>
#include <cmath>

#include "core/skin_model.hpp"
#include "kernels/device/space_alloc.hpp"
#include "kernels/neighbours/rebuild_watch.hpp"
#include "kernels/neighbours/verlet_list.hpp"
#include "kernels/solver/fused_step.hpp"
#include "kernels/solver/run_marks.hpp"
#include "kernels/solver/solver_parts.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths>
class ListKeeping {
 public:
  using Parts = SolverParts<V, ExecSpace, Paths>;
  using Real = typename Parts::Real;
  using Mem = typename Parts::Mem;
  using Policy = typename Parts::Types::Policy;
  static constexpr int Dim = Parts::Dim;

  explicit ListKeeping(Parts& parts) : s_(parts) {}

  // Whether some particle moved more than skin/2 since the last build: proved not by the
  // watch's bound when it can, else measured (neighbours/rebuild_watch.hpp). The exact
  // comparison is made in Real, so both ways rebuild at the same steps.
  bool expired() {
    if (!s_.watch.exact_known()) {
      if (s_.watch.bound_proves_valid()) return false;
      ++s_.exact_checks;
      s_.watch.measured(s_.global_max(s_.integrator.largest_displacement2(s_.p)));
    }
    return Real(s_.watch.exact_d2()) > rebuild_distance2();
  }
  // (skin/2)^2 in Real, as expired() compares (and the chained steps' device watch).
  Real rebuild_distance2() const { return Real(0.25) * s_.skin * s_.skin; }

  // Wraps periodic coordinates, hands particles between processes, deletes escaped ones,
  // sorts by cell and rebuilds the Verlet list; x_ref remembers where particles were, for
  // the skin criterion.
  void rebuild() {
    wrap_periodic();
    auto& p = s_.p;
    if (s_.slabs) s_.slabs->migrate(p, s_.permutation, grower());
    s_.population.remove_escaped(p, s_.permutation);
    s_.sort.sort(s_.grid, p.x, p.id, p.n);
    s_.permutation.apply(p, s_.sort.order, p.n);
    if (s_.slabs) {
      s_.slabs->append_ghosts(p, s_.sort.cell_start, s_.ghost_start, grower());
      s_.list.build(s_.grid, s_.box, s_.sort.cell_start, p.x, p.species, s_.table.radius, s_.skin,
                    p.n, GhostCells<Mem>{s_.ghost_start, p.n});
    } else {
      s_.list.build(s_.grid, s_.box, s_.sort.cell_start, p.x, p.species, s_.table.radius, s_.skin,
                    p.n);
    }
    copy_prefix<ExecSpace>(p.x_ref, p.x, int(p.x.extent(0)));  // space_alloc.hpp: not on OpenMP
    mark_runs();
    s_.watch.rebuilt();
    s_.last_build_interval = s_.builds > 0 ? s_.steps - s_.last_build_step : 0;
    ++s_.builds;
    s_.last_build_step = s_.steps;
  }

  // Grows the particle store to a capacity (slab exchange, ghosts).
  auto grower() {
    return [this](int capacity) { Parts::Population::grow(s_.p, capacity); };
  }

  // The marks of the fused step's work items (run_marks.hpp): which may touch the obstacle
  // and, on host paths, which may have a partner across a periodic face before the next
  // build, from where the particles were at the last build (x_ref): at a rebuild and when
  // a state is imported with its list. The fused step treats every particle of an item it
  // does not know as marked: the last item when it is not full (particles inserted since
  // fill it), or all of them before any marking.
  void mark_runs() {
    constexpr bool spans = Paths::host;  // the image's spans: host paths only
    if constexpr (V::obstacle::present || spans) {
      using Kernel = FusedStepKernel<V, ExecSpace, Paths>;
      auto& p = s_.p;
      const int runs = Kernel::work_items(p.n);
      if (int(s_.run_marks.extent(0)) < runs)
        s_.run_marks = decltype(s_.run_marks)(alloc_on<ExecSpace>("run_marks"),
                                              Kernel::work_items(p.capacity()));
      if (spans && int(s_.image_spans.extent(0)) < runs)
        s_.image_spans = decltype(s_.image_spans)(alloc_on<ExecSpace>("image_spans"),
                                                  Kernel::work_items(p.capacity()));
      const MarkRuns<Dim, Real, typename Parts::Obstacle, V::obstacle::present, Mem> mark{
          s_.run_marks,
          s_.image_spans,
          p.x_ref,
          p.species,
          s_.table.radius,
          s_.obstacle,
          s_.box,
          spans,
          double(s_.skin),
          double(s_.max_radius()),
          p.n,
          Kernel::run_length};
      Kokkos::parallel_for("run_marks", Policy(0, runs), mark);
      s_.run_marks_known = p.n / Kernel::run_length;  // the full runs
    }
  }

  // Adaptive skin, before a build that a displacement forced: the skin of least modelled
  // cost (core/skin_model.hpp) from the interval that ends here. Counts are summed over
  // processes and the displacement is the global one, so every rank picks the same skin.
  void choose_skin() {
    const long steps = s_.steps - s_.last_build_step;
    const long particles = s_.comm.sum(long(s_.p.n)), entries = s_.comm.sum(long(s_.list.total));
    if (steps <= 0 || particles <= 0) return;
    const SkinSample interval{double(s_.skin), double(entries) / double(particles),
                              std::sqrt(s_.watch.exact_d2()) / double(steps)};
    use_skin(s_.skin_model.best(interval));
  }
  void use_skin(double skin) {
    s_.skin = Real(skin);
    s_.watch = RebuildWatch(0.5 * double(s_.skin), double(Real(s_.setup.dt)));
  }

  // Public because it launches a KOKKOS_LAMBDA: nvcc rejects an extended lambda whose
  // enclosing member function is private or protected.
  void wrap_periodic() {
    const auto box = s_.box;
    const auto x = s_.p.x;
    Kokkos::parallel_for(
        "wrap_periodic", Policy(0, s_.p.n), KOKKOS_LAMBDA(const int i) {
          for (int d = 0; d < Dim; ++d) x(i, d) = box.wrap(d, x(i, d));
        });
  }

 private:
  Parts& s_;
};

}  // namespace granshock

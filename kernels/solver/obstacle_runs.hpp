// Which work items of the fused step can reach the obstacle before the next list build
// (docs/design.md, "The solver"). Testing every particle against the obstacle at every step
// cost the paper case about 10 instructions per particle-step and 5.5 % of its cycles
// (docs/benchmarks.md, "The paper case against the gas at the same N"), though only the few
// particles around it can touch it.
// Between two list builds no particle moves more than skin/2 from where it was at the
// build (neighbours/rebuild_watch.hpp), so one that touches the obstacle at some step was,
// at the build, closer to its centre than r_i + R + skin/2 (R: the disk's radius, or the
// radius of a circle about the centre that holds the polygon). At each build, and when a
// state is imported with its list, the work items (runs of particles on host paths, one
// particle on device paths) with such a particle at its reference position are marked,
// with a margin of a whole skin; the fused step tests the others' particles against
// nothing, except in a run it does not know (the last one when not full). The skipped test would
// have found no contact, and a particle whose spring with the obstacle is not zero is in a marked
// item (it touched it within the list's period, or at the step before this build), so the forces,
// springs and trajectories are bitwise those of the test at every particle (tests/unit/
// test_obstacle_runs.cpp).
#pragma once

#include <Kokkos_Core.hpp>
#include <cstdint>

#include "kernels/device/position.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

template <int Dim, class Real, class Obstacle, class MemSpace>
struct NearObstacleRuns {
  Kokkos::View<std::uint8_t*, MemSpace> near;  // per work item: 1 where it may touch
  Kokkos::View<Position* [Dim], MemSpace> x;   // at the build (= x_ref)
  Kokkos::View<int*, MemSpace> species;
  Kokkos::View<Real*, MemSpace> radius;  // per species
  Obstacle obstacle;
  double margin;  // the skin
  int n, run_length;

  KOKKOS_INLINE_FUNCTION void operator()(const int run) const {
    const int first = run * run_length;
    const int last = first + run_length < n ? first + run_length : n;
    std::uint8_t any = 0;
    for (int i = first; i < last; ++i) {
      double r2 = 0;
      for (int d = 0; d < (Dim == 3 ? 2 : Dim); ++d) {  // in 3-D the axis is along z
        const double dx = double(x(i, d) - obstacle.centre[d]);
        r2 += dx * dx;
      }
      const double reach = double(radius(species(i))) + double(obstacle.radius) + margin;
      if (r2 < reach * reach) any = 1;
    }
    near(run) = any;
  }
};

}  // namespace granshock

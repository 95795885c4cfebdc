// Which work items of the fused step need the obstacle test, and which the minimum image,
// before the next list build (docs/design.md, "The solver"). Both are known at a build:
// between two builds no particle moves more than skin/2 from where it was then
// (neighbours/rebuild_watch.hpp).
//
// The obstacle. Testing every particle against it at every step cost the paper case about
// 10 instructions per particle-step and 5.5 % of its cycles (docs/benchmarks.md, "The paper
// case against the gas at the same N"), though only the few particles around it can touch
// it. A particle that touches it at some step was, at the build, closer to its centre than
// r_i + R + skin/2 (R: the disk's radius, or the radius of a circle about the centre that
// holds the polygon); work items with a particle within r_i + R + skin are marked. A
// particle whose spring with the obstacle is not zero is in a marked item (it touched it
// within the list's period, or at the step before this build).
//
// The minimum image. A list partner is across a periodic face only if the particle was,
// at the build, within the list's reach c = 2 r_max + skin of a face (positions are then
// wrapped into the box, ghosts carry their owner's coordinates). A particle farther than
// c + skin from both faces has every partner within c of it without an image, and the two
// move at most a skin apart before the next build, so |x_i - x_j| stays below c + skin,
// which is at most half the box on that axis (else every particle is within c + skin of
// a face): BoxGeometry::nearby_image would leave every separation as it is. Particles
// within c + skin of a periodic face, or outside the box, need the image. Each work item
// keeps the span of its particles from the first to the last such one: cells are sorted
// with x fastest, so a run of 64 particles of a dilute gas spans most of a row, nearly
// every run holds a particle near an x face, and those particles are the end of one row
// and the start of the next, one stretch (a per-particle test in the force loop cost more
// than the image it saved: docs/benchmarks.md, "Instructions per particle-step"). Only
// host paths skip the image (a GPU thread's particle is one of 32 in a warp that would
// diverge).
//
// The fused step skips the obstacle test in the items not marked, and the image outside
// their spans, except in an item it does not know (the last one when not full).
// The skipped test would have found no contact and the skipped image changed nothing, so
// forces, springs and trajectories are bitwise those of the full test at every particle
// (tests/unit/test_run_marks.cpp, test_backend_agreement.cpp).
#pragma once

#include <Kokkos_Core.hpp>
#include <cstdint>

#include "kernels/device/box_geometry.hpp"
#include "kernels/device/position.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

// The bits of a work item's mark.
namespace run_mark {
constexpr std::uint8_t obstacle = 1;  // may touch the obstacle
constexpr std::uint8_t image = 2;     // may have a partner across a periodic face
constexpr std::uint8_t all = obstacle | image;
}  // namespace run_mark

// WithObstacle: the scene has one (Obstacle is then its geometry).
template <int Dim, class Real, class Obstacle, bool WithObstacle, class MemSpace>
struct MarkRuns {
  Kokkos::View<std::uint8_t*, MemSpace> marks;  // per work item: run_mark bits
  // Per work item: the particles [begin, end) that form the image, begin = end when none.
  Kokkos::View<int* [2], MemSpace> image_span;
  Kokkos::View<Position* [Dim], MemSpace> x;  // at the build (= x_ref)
  Kokkos::View<int*, MemSpace> species;
  Kokkos::View<Real*, MemSpace> radius;  // per species
  Obstacle obstacle;
  BoxGeometry<Dim, Position> box;
  bool with_images;  // mark the image bit and the spans (host paths); else the bit is set
                     // on every item, and image_span is not written
  double skin;
  double max_radius;  // of all species
  int n, run_length;

  KOKKOS_INLINE_FUNCTION void operator()(const int run) const {
    const int first = run * run_length;
    const int last = first + run_length < n ? first + run_length : n;
    std::uint8_t any = with_images ? 0 : run_mark::image;
    int begin = last, end = first;
    for (int i = first; i < last; ++i) {
      if constexpr (WithObstacle)
        if (near_obstacle(i)) any |= run_mark::obstacle;
      if (with_images && near_periodic_face(i)) {
        if (i < begin) begin = i;
        end = i + 1;
      }
    }
    if (with_images) {
      if (begin < end)
        any |= run_mark::image;
      else
        begin = end = first;
      image_span(run, 0) = begin;
      image_span(run, 1) = end;
    }
    marks(run) = any;
  }

  KOKKOS_INLINE_FUNCTION bool near_obstacle(const int i) const {
    double r2 = 0;
    for (int d = 0; d < (Dim == 3 ? 2 : Dim); ++d) {  // in 3-D the axis is along z
      const double dx = double(x(i, d) - obstacle.centre[d]);
      r2 += dx * dx;
    }
    const double reach = double(radius(species(i))) + double(obstacle.radius) + skin;
    return r2 < reach * reach;
  }

  // Within c + skin of a face of a periodic axis (open axes have image_length 0).
  KOKKOS_INLINE_FUNCTION bool near_periodic_face(const int i) const {
    const double margin = 2 * max_radius + 2 * skin;
    for (int d = 0; d < Dim; ++d) {
      if (box.image_length[d] == 0) continue;
      const double below = double(x(i, d) - box.lo[d]);
      const double above = double(box.lo[d] + box.length[d] - x(i, d));
      if (!(below >= margin && above >= margin)) return true;  // NaN: marked
    }
    return false;
  }
};

}  // namespace granshock

// The marks of the fused step's work items (kernels/solver/run_marks.hpp). The obstacle
// bit: set exactly when one of their particles is closer to the obstacle's centre than
// r_i + R + skin at the list build. The image bit: set exactly when one of their particles
// is within 2 r_max + 2 skin of a face of a periodic axis, or outside the box, and the span
// from the first such particle to the last. That the fused and closing passes, which test
// only the marked items against the obstacle and form the minimum image only in those, give
// bitwise the trajectory of device paths, which do both for every particle, is checked by
// KernelPaths.* (test_backend_agreement.cpp) on a periodic gas around a cylinder; the
// closing pass' forces against the unfused force pass by
// RecordedVirial.TheClosingPassRecordsTheForcesAndVirialOfASeparatePass.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cmath>
#include <optional>
#include <vector>

#include "core/material.hpp"
#include "kernels/models/no_obstacle.hpp"
#include "kernels/models/obstacle_body.hpp"
#include "kernels/solver/run_marks.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;

namespace {

using Geometry = ObstacleBody::Geometry<2, double>;
// Host memory and a host loop over the work items: the marking's arithmetic, whichever
// backend runs it (tests/ hold no kernel launch: .ci/run).
using Mem = Kokkos::HostSpace;

constexpr double kRadius = 0.5e-3, kSkin = 0.3e-3;

// Marks runs of `run_length` particles at `positions` (every particle of radius kRadius),
// in a box [0, 0.2] x [0, 0.4] periodic along the axes `periodic` (images: the image bit is
// worked out; else it is set on every run).
template <class Obstacle, bool WithObstacle>
std::vector<int> marks_of(const Obstacle& obstacle,
                          const std::vector<std::array<double, 2>>& positions, int run_length,
                          bool images, std::array<bool, 2> periodic = {true, true},
                          std::vector<std::array<int, 2>>* spans = nullptr) {
  const int n = int(positions.size()), runs = (n + run_length - 1) / run_length;
  Kokkos::View<Position* [2], Mem> x("x", n);
  Kokkos::View<int*, Mem> species("species", n);
  Kokkos::View<double*, Mem> radius("radius", 1);
  Kokkos::View<std::uint8_t*, Mem> marks("marks", runs);
  for (int i = 0; i < n; ++i) x(i, 0) = positions[i][0], x(i, 1) = positions[i][1];
  radius(0) = kRadius;
  Kokkos::View<int* [2], Mem> span("span", runs);
  Kokkos::deep_copy(span, -7);  // not written unless the image bit is worked out
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {0.2, 0.4, 0};
  box.periodic = {periodic[0], periodic[1], false};
  const MarkRuns<2, double, Obstacle, WithObstacle, Mem> mark{
      marks,  span,  x,       species, radius,    obstacle, BoxGeometry<2, Position>::from(box),
      images, kSkin, kRadius, n,       run_length};
  std::vector<int> out;
  for (int r = 0; r < runs; ++r) {
    mark(r);
    out.push_back(marks(r));
  }
  if (spans) {
    spans->clear();
    for (int r = 0; r < runs; ++r) spans->push_back({span(r, 0), span(r, 1)});
  }
  return out;
}

// The obstacle bits, with the image bit left out of the work (set on every run).
std::vector<int> marked_runs(const Geometry& obstacle,
                             const std::vector<std::array<double, 2>>& positions, int run_length) {
  std::vector<int> out;
  for (const int m : marks_of<Geometry, true>(obstacle, positions, run_length, false)) {
    EXPECT_EQ(m & run_mark::image, run_mark::image);
    out.push_back(m & run_mark::obstacle);
  }
  return out;
}

using Spans = std::vector<std::array<int, 2>>;

// The image bits of a scene without obstacle; the runs' spans of particles that form the
// image into spans.
std::vector<int> image_runs(const std::vector<std::array<double, 2>>& positions, int run_length,
                            std::array<bool, 2> periodic, Spans& spans) {
  std::vector<int> out;
  for (const int m : marks_of<NoObstacle::Geometry<2, double>, false>({}, positions, run_length,
                                                                      true, periodic, &spans)) {
    EXPECT_EQ(m & run_mark::obstacle, 0);
    out.push_back(m == run_mark::image ? 1 : 0);
  }
  return out;
}

Geometry cylinder(double diameter) {
  return Geometry::from(
      make_obstacle(ObstacleShape::cylinder, {0.1, 0.2, 0}, {diameter}, aluminium()));
}

}  // namespace

TEST(ObstacleRuns, MarksARunWithOneParticleInsideTheReachPlusASkin) {
  const double R = 5e-3, reach = R + kRadius + kSkin;
  const auto at = [](double distance, double angle) {
    return std::array<double, 2>{0.1 + distance * std::cos(angle),
                                 0.2 + distance * std::sin(angle)};
  };
  const std::vector<std::array<double, 2>> positions{at(3 * reach, 0.0),
                                                     at(4 * reach, 1.0),
                                                     at(2 * reach, 2.0),  // run 0: far
                                                     at(3 * reach, 0.0),
                                                     at(reach * (1 - 1e-9), 2.5),
                                                     at(5 * reach, 1.0),  // run 1: one inside
                                                     at(reach * (1 + 1e-9), 0.3),
                                                     at(3 * reach, 3.0),
                                                     at(2 * reach, 4.0),  // run 2: just outside
                                                     at(R, 1.2)};         // run 3 (short): touching
  EXPECT_EQ(marked_runs(cylinder(2 * R), positions, 3), (std::vector<int>{0, 1, 0, 1}));
  // One particle per work item, as on device paths.
  EXPECT_EQ(marked_runs(cylinder(2 * R), positions, 1),
            (std::vector<int>{0, 0, 0, 0, 1, 0, 0, 0, 0, 1}));
}

TEST(ObstacleRuns, APolygonReachesAsFarAsItsFarthestCorner) {
  // A plate 4 mm wide and 2 mm thick: its corners, (+-2, +-1) mm from the centre, are
  // sqrt(1 + 4) mm from the centre. A particle off a corner, along the diagonal, is marked;
  // one off the middle of a face at the same distance is marked too (the bound is the
  // circle about the centre), and one beyond the circle's reach is not.
  const Obstacle plate = make_obstacle(ObstacleShape::plate, {0.1, 0.2, 0}, {4e-3, 2e-3});
  const Geometry g = Geometry::from(plate);
  const double corner = std::sqrt(5.0) * 1e-3, reach = corner + kRadius + kSkin;
  EXPECT_NEAR(g.radius, corner, 1e-15);
  const double diagonal = reach * (1 - 1e-9) / std::sqrt(5.0);
  EXPECT_EQ(marked_runs(g, {{0.1 + diagonal * 2, 0.2 + diagonal * 1}}, 1), std::vector<int>{1});
  EXPECT_EQ(marked_runs(g, {{0.1 + reach * (1 - 1e-9), 0.2}}, 1), std::vector<int>{1});
  EXPECT_EQ(marked_runs(g, {{0.1, 0.2 - reach * (1 + 1e-9)}}, 1), std::vector<int>{0});
}

TEST(RunMarks, ImageBitWithinTheListReachPlusASkinOfAPeriodicFace) {
  // Reach c = 2 r + skin of a list partner, one skin more for the motion before the next
  // build: margin 2 r + 2 skin from a face.
  const double margin = 2 * kRadius + 2 * kSkin, in = margin * (1 - 1e-9),
               out = margin * (1 + 1e-9);
  const std::vector<std::array<double, 2>> positions{
      {0.1, 0.2},       {out, 0.2},      {0.2 - out, 0.2},  // run 0: all clear
      {0.1, 0.2},       {0.2 - in, 0.2}, {0.1, 0.2},        // run 1: near x = 0.2
      {0.1, in},        {0.1, 0.2},      {0.1, 0.2},        // run 2: near y = 0
      {0.1, 0.4 - out}, {0.1, out},      {out, 0.4 - out},  // run 3: all clear
      {0.1, 0.2},       {-1e-6, 0.2}};                      // run 4 (short): outside
  Spans spans;
  EXPECT_EQ(image_runs(positions, 3, {true, true}, spans), (std::vector<int>{0, 1, 1, 0, 1}));
  EXPECT_EQ(spans, (Spans{{0, 0}, {4, 5}, {6, 7}, {9, 9}, {13, 14}}));
  // Along an open axis nothing is marked: y open, x periodic.
  EXPECT_EQ(image_runs(positions, 3, {true, false}, spans), (std::vector<int>{0, 1, 0, 0, 1}));
  EXPECT_EQ(spans, (Spans{{0, 0}, {4, 5}, {6, 6}, {9, 9}, {13, 14}}));
  // Nothing periodic: no image anywhere, not even outside the box.
  EXPECT_EQ(image_runs(positions, 3, {false, false}, spans), (std::vector<int>{0, 0, 0, 0, 0}));
  EXPECT_EQ(spans, (Spans{{0, 0}, {3, 3}, {6, 6}, {9, 9}, {12, 12}}));
}

TEST(RunMarks, TheImageSpanRunsFromTheFirstToTheLastParticleNearAFace) {
  // The end of one row of cells and the start of the next: near x = 0.2, then near x = 0;
  // a particle between them in the run is inside the span too (it forms the image, which
  // changes nothing for it), the clear ones before and after are not.
  const double margin = 2 * kRadius + 2 * kSkin;
  const std::vector<std::array<double, 2>> positions{
      {0.1, 0.2}, {0.2 - margin / 2, 0.2}, {0.1, 0.2}, {margin / 2, 0.21}, {0.1, 0.21}};
  Spans spans;
  EXPECT_EQ(image_runs(positions, 5, {true, false}, spans), (std::vector<int>{1}));
  EXPECT_EQ(spans, (Spans{{1, 4}}));
}

TEST(RunMarks, APeriodicAxisShorterThanTwiceTheMarginMarksEveryParticle) {
  // In [0, 0.2] every position is within 0.1 of a face: with a margin above that, no
  // particle may skip the image (run_marks.hpp: |x_i - x_j| could exceed half the box).
  const double r = 0.02, skin = 0.031;  // margin 2 r + 2 skin = 0.102
  Kokkos::View<Position* [2], Mem> x("x", 2);
  Kokkos::View<int*, Mem> species("species", 2);
  Kokkos::View<double*, Mem> radius("radius", 1);
  Kokkos::View<std::uint8_t*, Mem> marks("marks", 2);
  Kokkos::View<int* [2], Mem> span("span", 2);
  x(0, 0) = 0.1, x(0, 1) = 0.2;         // the middle of the box
  x(1, 0) = 0.1 - 1e-9, x(1, 1) = 0.2;  // just off it
  radius(0) = r;
  Box box;
  box.lo = {0, 0, 0};
  box.hi = {0.2, 0.4, 0};
  box.periodic = {true, false, false};
  const MarkRuns<2, double, NoObstacle::Geometry<2, double>, false, Mem> mark{
      marks, span, x, species, radius, {}, BoxGeometry<2, Position>::from(box),
      true,  skin, r, 2,       1};
  mark(0);
  mark(1);
  EXPECT_EQ(int(marks(0)), int(run_mark::image));  // the farthest from both faces
  EXPECT_EQ(int(marks(1)), int(run_mark::image));
  EXPECT_EQ(span(0, 0), 0);
  EXPECT_EQ(span(0, 1), 1);
  EXPECT_EQ(span(1, 0), 1);
  EXPECT_EQ(span(1, 1), 2);
}

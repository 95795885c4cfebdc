// The fused step's work items that may touch the obstacle (kernels/solver/obstacle_runs.hpp):
// marked exactly when one of their particles is closer to the obstacle's centre than
// r_i + R + skin at the list build. That the fused step, which tests only those, gives
// bitwise the trajectory of the force pass that tests every particle is checked by
// FusedStep.MatchesSeparateHalvesWithFrictionAndObstacle (test_backend_agreement.cpp).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cmath>
#include <optional>
#include <vector>

#include "core/material.hpp"
#include "kernels/models/obstacle_body.hpp"
#include "kernels/solver/obstacle_runs.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;

namespace {

using Geometry = ObstacleBody::Geometry<2, double>;
// Host memory and a host loop over the work items: the marking's arithmetic, whichever
// backend runs it (tests/ hold no kernel launch: .ci/run).
using Mem = Kokkos::HostSpace;

constexpr double kRadius = 0.5e-3, kSkin = 0.3e-3;

// Marks runs of `run_length` particles at `positions` (every particle of radius kRadius).
std::vector<int> marked_runs(const Geometry& obstacle,
                             const std::vector<std::array<double, 2>>& positions, int run_length) {
  const int n = int(positions.size()), runs = (n + run_length - 1) / run_length;
  Kokkos::View<Position* [2], Mem> x("x", n);
  Kokkos::View<int*, Mem> species("species", n);
  Kokkos::View<double*, Mem> radius("radius", 1);
  Kokkos::View<std::uint8_t*, Mem> near("near", runs);
  for (int i = 0; i < n; ++i) x(i, 0) = positions[i][0], x(i, 1) = positions[i][1];
  radius(0) = kRadius;
  const NearObstacleRuns<2, double, Geometry, Mem> mark{near,     x,     species, radius,
                                                        obstacle, kSkin, n,       run_length};
  std::vector<int> out;
  for (int r = 0; r < runs; ++r) {
    mark(r);
    out.push_back(near(r));
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

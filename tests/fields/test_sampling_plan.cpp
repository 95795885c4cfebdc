// Where a bow-shock run puts its bins (cases/bow_shock/sampling_plan.cpp; docs/fields.md,
// section 1): the grid tiles the whole domain, one column is centred on the obstacle's axis
// and a row edge lies on its upstream face; the stagnation-line profile is centred on the
// axis and ends on the face. Checked for the default scene, the paper's scenes (whose
// 500 d width is no multiple of the 3 d bin) and an obstacle off the centre line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cases/bow_shock/sampling_plan.hpp"
#include "io/scene_file.hpp"
#include "kernels/sampling/bin_accumulator.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(GRANSHOCK_SOURCE_DIR) / "scenes";

struct Case {
  const char* scene;
  std::vector<std::string> sets;
};

// How far x is from a whole multiple of `step` (in steps).
double off_grid(double x, double step) {
  return std::abs(x / step - std::round(x / step));
}

class AlignedGrid : public testing::TestWithParam<Case> {};

TEST_P(AlignedGrid, TilesTheDomainWithAColumnOnTheAxisAndARowEdgeOnTheFace) {
  const Scene s = load_scene_file(kScenes / GetParam().scene, GetParam().sets).scene;
  const SamplingPlan plan(s);
  const BinLayout& g = plan.layout().grid;
  const Box& box = s.setup.box;
  const Obstacle& c = *s.setup.obstacle;
  const double width = box.length(0), face = c.centre[1] - 0.5 * CylinderShape::diameter(c);

  // Every column whole, the columns together exactly the periodic width.
  EXPECT_NEAR(g.nx * g.dx, width, 1e-12 * width);
  EXPECT_EQ(g.x_period, width);
  EXPECT_GE(g.x0, box.lo[0]);
  EXPECT_LT(g.x0, box.lo[0] + g.dx);
  // Bins within 10 % of the size the scene asks for.
  EXPECT_NEAR(g.dx / s.bin_size_m, 1.0, 0.1);
  EXPECT_NEAR(g.dy / s.bin_size_m, 1.0, 0.1);
  // A column centred on the axis: the axis lies half a bin from a column edge.
  EXPECT_NEAR(off_grid(c.centre[0] - g.x0 - 0.5 * g.dx, g.dx), 0.0, 1e-9);
  // A row edge on the face, rows from the inlet to past the outlet.
  EXPECT_EQ(g.y0, box.lo[1]);
  EXPECT_NEAR(off_grid(face - g.y0, g.dy), 0.0, 1e-9);
  EXPECT_GE(g.y0 + g.ny * g.dy, box.hi[1] - 1e-12);
  EXPECT_LT(g.y0 + (g.ny - 1) * g.dy, box.hi[1]);

  // Every position of the domain falls in a bin; the column on the axis holds the axis.
  const GridIndex where = GridIndex::of(g);
  int row = 0;
  const double y = 0.5 * face;
  for (double x : {box.lo[0], box.lo[0] + 1e-9, g.x0 - 1e-9, g.x0, box.hi[0] - 1e-9})
    EXPECT_GE(where(x, y, row), 0) << "x = " << x;
  const int axis_bin = where(c.centre[0], y, row);
  EXPECT_NEAR(g.x0 + (axis_bin % g.nx + 0.5) * g.dx, c.centre[0], 1e-9 * width);
  // Left of x0 is the wrapped last column, the same as just below the domain's end.
  if (g.x0 > box.lo[0]) {
    EXPECT_EQ(where(box.lo[0], y, row) % g.nx, g.nx - 1);
    EXPECT_EQ(where(box.hi[0] - 1e-9, y, row) % g.nx, g.nx - 1);
  }
  EXPECT_EQ(where(c.centre[0], box.hi[1] - 1e-9, row) / g.nx, g.ny - 1);

  // The profile: centred on the axis, ending on the face, rows of about 0.5 d.
  ASSERT_TRUE(plan.layout().has_profile());
  const BinLayout& p = plan.layout().profile;
  EXPECT_EQ(p.nx, SamplingPlan::kProfileColumns);
  EXPECT_NEAR(p.x0 + 0.5 * p.nx * p.dx, c.centre[0], 1e-12 * width);
  EXPECT_NEAR(p.y0 + p.ny * p.dy, face, 1e-12 * face);
  EXPECT_NEAR(p.dy / (0.5 * s.d_m), 1.0, 0.05);
  EXPECT_EQ(p.x_period, 0);
  EXPECT_EQ(p.blocks, g.blocks);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, AlignedGrid,
    testing::Values(Case{"default.toml", {}}, Case{"paper/d100_u1000.toml", {}},
                    Case{"paper/d10_u2375.toml", {}},
                    Case{"default.toml", {"obstacle.centre=[\"40.3 d\", \"101.7 d\"]"}},
                    Case{"default.toml", {"numerics.bin_size=\"2.3 d\""}}));

}  // namespace

// docs/fields.md: the sonic line of an analytic Mach field Ma = r/r0,
// sampled on bin centres, is found within a tenth of a bin of r = r0 by marching squares;
// masked (NaN) bins break the line.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/iso_lines.hpp"

using namespace granshock;

namespace {

// Bins of 3 mm; 40 x 40 centres; a circle of radius r0 = 10 bins around a point off the
// grid's symmetry so that crossings fall at all fractions of a bin.
constexpr double kBin = 3e-3, kR0 = 10 * kBin, kXc = 20.3 * kBin, kYc = 19.6 * kBin;

NodeGrid centres() {
  return NodeGrid{40, 40, 0.5 * kBin, 0.5 * kBin, kBin, kBin};
}

std::vector<double> mach_field(const NodeGrid& g) {
  std::vector<double> ma;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix)
      ma.push_back(std::hypot(g.x0 + ix * g.dx - kXc, g.y0 + iy * g.dy - kYc) / kR0);
  return ma;
}

}  // namespace

TEST(SonicLine, AnalyticMachFieldWithinATenthOfABin) {
  const NodeGrid g = centres();
  const std::vector<Polyline> lines = iso_lines(mach_field(g), g, 1.0);
  ASSERT_EQ(lines.size(), 1u);
  const Polyline& line = lines[0];
  ASSERT_GT(line.size(), 60u);  // about 2 pi r0 / bin * 1.3 crossings
  // Closed: the loop returns to its first point.
  EXPECT_DOUBLE_EQ(line.front().x, line.back().x);
  EXPECT_DOUBLE_EQ(line.front().y, line.back().y);
  double worst = 0, turn = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    worst = std::max(worst, std::abs(std::hypot(line[i].x - kXc, line[i].y - kYc) - kR0));
    if (i > 0) {
      double dphi = std::atan2(line[i].y - kYc, line[i].x - kXc) -
                    std::atan2(line[i - 1].y - kYc, line[i - 1].x - kXc);
      dphi -= 2 * M_PI * std::round(dphi / (2 * M_PI));
      turn += dphi;
    }
  }
  EXPECT_LT(worst, 0.1 * kBin) << "largest distance from r = r0";
  EXPECT_NEAR(std::abs(turn), 2 * M_PI, 1e-9) << "the line goes once around the centre";
}

TEST(SonicLine, MaskedBinsBreakTheLine) {
  const NodeGrid g = centres();
  std::vector<double> ma = mach_field(g);
  // Mask the column of centres nearest x = xc: the loop is cut into two open arcs.
  for (int iy = 0; iy < g.ny; ++iy) ma[static_cast<std::size_t>(iy * g.nx + 20)] = std::nan("");
  const std::vector<Polyline> lines = iso_lines(ma, g, 1.0);
  ASSERT_EQ(lines.size(), 2u);
  for (const Polyline& line : lines) {
    EXPECT_FALSE(line.front().x == line.back().x && line.front().y == line.back().y) << "open";
    for (const Point2& p : line) {
      EXPECT_LT(std::abs(std::hypot(p.x - kXc, p.y - kYc) - kR0), 0.1 * kBin);
      // No point inside the masked column's cells.
      EXPECT_FALSE(p.x > g.x0 + 19 * kBin + 1e-12 && p.x < g.x0 + 21 * kBin - 1e-12);
    }
  }
}

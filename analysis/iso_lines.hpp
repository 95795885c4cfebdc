// Iso-lines of a field sampled on the nodes of a regular grid, by marching squares: the
// sonic line Ma = 1 (docs/fields.md) is iso_lines(Ma, ..., 1) on the bin centres.
#pragma once

#include <vector>

#include "analysis/polyline.hpp"

namespace granshock {

struct NodeGrid {
  int nx = 0, ny = 0;     // nodes across and along
  double x0 = 0, y0 = 0;  // position of node (0, 0)
  double dx = 1, dy = 1;  // node spacing
};

// values: [ny][nx] row-major, node (ix, iy) at (x0 + ix dx, y0 + iy dy). Each grid cell
// whose four corners are finite contributes the segments where the bilinear-free linear
// interpolation along its edges crosses `level` (a corner equal to the level counts as
// above it); the two saddle cases are resolved with the mean of the four corners. A cell
// with a NaN corner (a masked bin) contributes nothing, so lines end there. Segments that
// share an edge crossing are joined into polylines; a closed loop repeats its first point
// at its end. Lines are returned in a deterministic order (by their first crossing).
std::vector<Polyline> iso_lines(const std::vector<double>& values, const NodeGrid& grid,
                                double level);

}  // namespace granshock

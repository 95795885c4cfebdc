// Points and polylines in the x-y plane (m), the shape of the derived lines: the sonic
// line and the shock front.
#pragma once

#include <vector>

namespace granshock {

struct Point2 {
  double x = 0, y = 0;
};
using Polyline = std::vector<Point2>;

}  // namespace granshock

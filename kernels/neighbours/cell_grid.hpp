// A regular grid of cells over the box, at least one interaction range wide, so that
// every partner of a particle lies in its own or an adjacent cell. Periodic axes wrap;
// on open axes positions outside the box are clamped to the edge cells (clamping is
// monotonic, so neighbours stay in adjacent cells).
#pragma once

#include <Kokkos_Core.hpp>
#include <cmath>

#include "core/user_error.hpp"
#include "kernels/device/box_geometry.hpp"
#include "kernels/device/device_math.hpp"
#include "kernels/device/vec.hpp"

namespace granshock {

template <int Dim, class Real>
struct CellGrid {
  Real lo[Dim];
  Real inv_cell[Dim];
  int ncell[Dim];
  bool periodic[Dim];

  static CellGrid make(const Box& box, double min_cell_size) {
    CellGrid g;
    for (int d = 0; d < Dim; ++d) {
      const double len = box.length(d);
      g.ncell[d] = len >= min_cell_size ? int(len / min_cell_size) : 1;
      g.lo[d] = Real(box.lo[d]);
      g.inv_cell[d] = Real(g.ncell[d] / len);
      g.periodic[d] = box.periodic[d];
      if (g.periodic[d] && g.ncell[d] < 3)
        throw UserError("periodic box axis " + std::to_string(d) + " is " + std::to_string(len) +
                        " m long; it must hold at least 3 interaction " + "ranges (" +
                        std::to_string(3 * min_cell_size) + " m)");
    }
    return g;
  }

  // The geometric mean of the cell sizes (host): the size of a cube of a cell's volume.
  double mean_cell_size() const {
    double volume = 1;
    for (int d = 0; d < Dim; ++d) volume /= double(inv_cell[d]);
    return std::pow(volume, 1.0 / Dim);
  }

  int total() const {
    int t = 1;
    for (int d = 0; d < Dim; ++d) t *= ncell[d];
    return t;
  }

  KOKKOS_INLINE_FUNCTION int coord(int d, Real x) const {
    const int c = int(dmath::floor((x - lo[d]) * inv_cell[d]));
    return c < 0 ? 0 : (c >= ncell[d] ? ncell[d] - 1 : c);
  }

  KOKKOS_INLINE_FUNCTION int flat(const int (&c)[Dim]) const {
    int idx = 0;
    for (int d = Dim - 1; d >= 0; --d) idx = idx * ncell[d] + c[d];
    return idx;
  }

  template <class PositionView>
  KOKKOS_INLINE_FUNCTION int cell_of(const PositionView& x, int i) const {
    int c[Dim];
    for (int d = 0; d < Dim; ++d) c[d] = coord(d, x(i, d));
    return flat(c);
  }

  // The k-th of the 3^Dim cells around cell coordinates c, or -1 when it falls off an
  // open edge.
  KOKKOS_INLINE_FUNCTION int neighbour(const int (&c)[Dim], int k) const {
    int nc[Dim];
    for (int d = 0; d < Dim; ++d) {
      nc[d] = c[d] + (k % 3) - 1;
      k /= 3;
      if (nc[d] < 0 || nc[d] >= ncell[d]) {
        if (!periodic[d]) return -1;
        nc[d] = (nc[d] + ncell[d]) % ncell[d];
      }
    }
    return flat(nc);
  }

  KOKKOS_INLINE_FUNCTION static constexpr int neighbour_count() { return Dim == 2 ? 9 : 27; }
};

}  // namespace granshock

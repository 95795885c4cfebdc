// The field accumulators of a run as `granshock run` stores them in run.h5 (docs/fields.md;
// layout of each bin's quantities in core/bin_layout.hpp; the file's reader and writer are
// io/field_sums_file.hpp): per block, bin and quantity a
// SUM over all samples of that block, and the number of samples of each block. Two sets
// exist: the coarse grid over the whole domain (/fields/grid) and the finer stagnation-line
// profile (/fields/profile), narrow columns on the obstacle's axis cut into short rows.
#pragma once

#include <algorithm>
#include <limits>
#include <vector>

#include "core/bin_layout.hpp"

namespace granshock {

struct BinSums {
  int n_species = 2;
  int nx = 1, ny = 1;
  int blocks = 1;
  double x0 = 0, y0 = 0;  // lower-left corner of bin (0, 0), m
  double dx = 0, dy = 0;  // bin width (x) and height (y), m
  double x_period = 0;    // > 0: the last column wraps across the periodic x boundary
  int dim = 2;            // 3: columns through a layer `depth` thick, with z moments
  double depth = 0;       // 3-D only: the columns' extent along z from z0, m
  double z0 = 0;
  // Where the domain ends along y: a last row reaching past it covers only the part below
  // (infinite: every row is whole).
  double y_end = std::numeric_limits<double>::infinity();
  // Production window the sums cover (s); NaN when the file does not say.
  double production_start = 0, production_end = 0;
  std::vector<double> sums;     // [blocks][ny][nx][quantities()], row-major
  std::vector<double> samples;  // [blocks]

  BinLayout layout() const;  // the index arithmetic
  int quantities() const { return layout().quantities(); }
  int bins() const { return nx * ny; }
  // The area of a bin of row iy inside the domain (the last row may be clipped at y_end).
  double bin_area(int iy) const {
    const double top = y0 + (iy + 1) * dy;
    return dx * (top <= y_end ? dy : std::max(0.0, y_end - (y0 + iy * dy)));
  }
  // Its area (2-D) or volume, the area times the depth (3-D): what densities divide by.
  double bin_measure(int iy) const { return dim == 3 ? bin_area(iy) * depth : bin_area(iy); }
  double x_centre(int ix) const { return x0 + (ix + 0.5) * dx; }
  double y_centre(int iy) const { return y0 + (iy + 0.5) * dy; }
  double total_samples() const;
  // The sum of quantity q of bin (iy, ix) over every block.
  double pooled(int iy, int ix, int q) const;

  // The sums of one block only (blocks = 1).
  BinSums block(int b) const;
  // All blocks added into one (blocks = 1).
  BinSums pooled_blocks() const;
  // Bin column ix alone (nx = 1), every block: a stand-in for the stagnation-line
  // profile when a run file has none.
  BinSums column(int ix) const { return columns(ix, ix + 1); }
  // Columns [ix_begin, ix_end) added into one column (a wider strip), every block.
  BinSums columns(int ix_begin, int ix_end) const;
  // Rows merged k at a time into rows k dy high, counted back from row `row_end` (whose
  // lower edge stays a row edge); rows below the last whole group are dropped, and so are
  // rows from row_end on.
  BinSums merged_rows(int k, int row_end) const;
  // Blocks [b_begin, b_end) only.
  BinSums block_range(int b_begin, int b_end) const;
  // One block, the sum of block b taken weights[b] times (a bootstrap resample).
  BinSums weighted_blocks(const std::vector<int>& weights) const;

  // Throws std::invalid_argument when sizes and shape disagree.
  void check_consistent() const;
};

}  // namespace granshock

// The field accumulators of a run as `granshock run` stores them in run.h5 (docs/fields.md;
// layout of each bin's quantities in core/bin_layout.hpp; the file's reader and writer are
// io/field_sums_file.hpp): per block, bin and quantity a
// SUM over all samples of that block, and the number of samples of each block. Two sets
// exist: the coarse grid over the whole domain (/fields/grid) and the finer stagnation-line
// profile (/fields/profile), a strip x in [x_lo, x_hi] cut along y into bins of dy.
#pragma once

#include <vector>

#include "bin_layout.hpp"

namespace granshock {

struct BinSums {
  int n_species = 2;
  int nx = 1, ny = 1;
  int blocks = 1;
  double x0 = 0, y0 = 0;  // lower-left corner of bin (0, 0), m
  double dx = 0, dy = 0;  // bin width (x) and height (y), m
  // Production window the sums cover (s); NaN when the file does not say.
  double production_start = 0, production_end = 0;
  std::vector<double> sums;     // [blocks][ny][nx][quantities()], row-major
  std::vector<double> samples;  // [blocks]

  BinLayout layout() const;  // the index arithmetic (bin_size of a square bin = dx)
  int quantities() const { return layout().quantities(); }
  int bins() const { return nx * ny; }
  double bin_area() const { return dx * dy; }
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
  BinSums column(int ix) const;

  // Throws std::invalid_argument when sizes and shape disagree.
  void check_consistent() const;
};

}  // namespace granshock

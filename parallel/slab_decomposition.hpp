// The spatial decomposition of the box into slabs along one axis, x (0) or y (1), whose
// cell layers across the axis (grid columns or grid rows) are called rows here
// (docs/parallel.md): rank r
// owns the coordinates [cut(r), cut(r+1)). Cuts lie on cell-row boundaries, so that every
// rank sorts its particles into the same global cells and the pair order of a particle
// (cell, then global id) is the same for any number of ranks. A slab is at least one
// halo wide (the pair cutoff plus the skin), so ghosts come only from the two adjacent
// slabs. The decomposition is a pure function of its inputs: every rank computes the same.
#pragma once

#include <vector>

namespace granshock {

class SlabDecomposition {
 public:
  // The axis from `lo`, `length` long, in `rows` cell rows (the cell grid's); `min_rows`
  // rows per slab at least. Equal slabs (in rows; the first `rows % ranks` one row wider).
  // Too many ranks for the rows is a UserError naming the axis.
  static SlabDecomposition equal(int ranks, int axis, double lo, double length, int rows,
                                 int min_rows, bool periodic);
  // Slabs holding as equal shares of `count_per_row` (particles per cell row, summed over
  // every rank) as row boundaries and `min_rows` allow: cut k at the row boundary nearest
  // to k/ranks of the total (the lower one on a tie).
  static SlabDecomposition balanced(int ranks, int axis, double lo, double length,
                                    const std::vector<long>& count_per_row, int min_rows,
                                    bool periodic);

  // The same axis cut anew by `count_per_row`, as balanced() with this one's minimum.
  SlabDecomposition rebalanced(const std::vector<long>& count_per_row) const {
    return balanced(ranks(), axis_, lo_, length_, count_per_row, min_rows_, periodic_);
  }
  // The largest total of `count_per_row` over the rows of one slab.
  long heaviest(const std::vector<long>& count_per_row) const;

  int axis() const { return axis_; }
  int ranks() const { return int(first_row_.size()) - 1; }
  int rows() const { return first_row_.back(); }
  int first_row(int rank) const { return first_row_[rank]; }
  int end_row(int rank) const { return first_row_[rank + 1]; }
  double lower(int rank) const { return lo_ + first_row_[rank] * (length_ / rows()); }
  double upper(int rank) const { return lo_ + first_row_[rank + 1] * (length_ / rows()); }

  // The rank owning a coordinate: by its cell row, as the cell sort computes it; rows
  // before the first and past the last (a particle outside an open box before its
  // removal) belong to the end slabs.
  int owner(double coordinate) const;
  // The rank owning a cell row (0 <= row < rows()).
  int owner_of_row(int row) const;
  // The row of a coordinate, unclamped; the arithmetic of CellGrid::coord (kernels/
  // neighbours/cell_grid.hpp), so that a slab boundary is a cell boundary to the last bit.
  long row_of(double coordinate) const;
  // The ranks that hold ghosts of `rank`'s particles, or whose particles are ghosts of it:
  // the adjacent slabs (wrapping if periodic), each once, never `rank` itself.
  std::vector<int> neighbours(int rank) const;

 private:
  SlabDecomposition(int axis, double lo, double length, std::vector<int> first_row, int min_rows,
                    bool periodic);
  int axis_ = 1;
  double lo_ = 0;
  double length_ = 1;
  double inv_row_width_ = 1;    // rows / length, as the cell grid computes it
  std::vector<int> first_row_;  // ranks + 1 entries; first_row_[0] = 0
  int min_rows_ = 1;
  bool periodic_ = false;
};

}  // namespace granshock

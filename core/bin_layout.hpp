// The layout of the field accumulators (docs/fields.md), shared by the device kernels that
// fill them during a run and the analysis that turns them into fields.
//
// Per bin and per species a, every sample adds
//   N_a, sum c_x, sum c_y, sum c_x c_x, sum c_x c_y, sum c_y c_y        (6 per species)
// and, for the mixture, the contact virial of the particles in the bin
//   sum over contacts of 1/2 r_ij (x) F_ij: W_xx, W_xy, W_yx, W_yy        (4)
// (each particle carries half of each of its contacts; r_ij = x_i - x_j, F_ij the force
// on i), so that the collisional stress of a bin is -<W>/V_bin. A 3-D scene's bins are
// columns through the layer (docs/fields.md, "Three dimensions"); after the 2-D quantities
// come, per species, sum c_z and sum c_z c_z, then W_zz for the mixture (2 n_species + 1).
// Sums are kept per block: the production window is cut into `blocks` equal parts, so
// that statistical uncertainties follow from block averages.
#pragma once

namespace granshock {

struct BinLayout {
  int n_species = 2;
  int nx = 1, ny = 1;           // bins across (x) and along (y) the flow
  double x0 = 0, y0 = 0;        // lower-left corner of bin (0, 0), m
  double dx = 3e-3, dy = 3e-3;  // bin width (x) and height (y), m
  // > 0: the columns tile a periodic x axis of this length, and a position left of x0
  // belongs to the last column (the one that wraps across the periodic boundary).
  double x_period = 0;
  int blocks = 10;
  int dim = 2;       // 3: the z moments follow (depth_index, w_zz_index)
  double depth = 0;  // 3-D: the columns' extent along z from z0 (the layer's thickness), m
  double z0 = 0;     // 3-D: the columns' lower end (a sphere's centre-plane cut)

  static constexpr int per_species = 6;
  enum SpeciesQuantity { count = 0, sum_vx, sum_vy, sum_vxvx, sum_vxvy, sum_vyvy };
  enum VirialQuantity { w_xx = 0, w_xy, w_yx, w_yy };
  enum DepthQuantity { sum_vz = 0, sum_vzvz };

  int depth_quantities() const { return dim == 3 ? 2 * n_species + 1 : 0; }
  int quantities() const { return per_species * n_species + 4 + depth_quantities(); }
  int species_index(int species, SpeciesQuantity q) const { return per_species * species + q; }
  int virial_index(VirialQuantity q) const { return per_species * n_species + q; }
  int depth_index(int species, DepthQuantity q) const {
    return per_species * n_species + 4 + 2 * species + q;
  }
  int w_zz_index() const { return per_species * n_species + 4 + 2 * n_species; }
  int bins() const { return nx * ny; }
  // Offset of (block, bin iy, bin ix, quantity) in the flat row-major array
  // [blocks][ny][nx][quantities].
  long offset(int block, int iy, int ix, int q) const {
    return ((long(block) * ny + iy) * nx + ix) * quantities() + q;
  }
};

// How sampled values are scattered into bins on the device (measured against each other
// in docs/fields.md, "Cost of sampling"): atomic adds, a ScatterView, or rows of bins
// owned by threads (each thread scans every particle and adds those in its rows, without
// atomics and in particle order, so the sums are bitwise the same for any thread count;
// for host backends, where threads are few). automatic: rows on a host backend with at
// most 16 threads, atomic otherwise.
enum class ScatterStrategy { automatic, atomic, scatter_view, rows };

// What a run samples: the grid over the whole domain and, with an obstacle, the finer
// stagnation-line profile, a block of narrow columns centred on the obstacle's axis cut
// into short rows (the same quantities per bin; docs/fields.md, section 1).
struct FieldSampling {
  BinLayout grid;
  BinLayout profile = no_profile();
  ScatterStrategy strategy = ScatterStrategy::automatic;

  bool has_profile() const { return profile.nx > 0 && profile.ny > 0; }
  static BinLayout no_profile() {
    BinLayout none;
    none.nx = none.ny = 0;
    return none;
  }
};

}  // namespace granshock

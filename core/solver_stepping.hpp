// The stepping part of the solver interface (core/solver.hpp): particles in, the time
// loop, insertion and deletion at open boundaries, and how several processes divide the
// box.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/host_particles.hpp"

namespace granshock {

// New particles for a rectangular region (2-D: x and y ranges), placed at random
// without overlapping each other or particles already there.
struct InsertionRequest {
  std::array<double, 2> x_range{0, 0};
  std::array<double, 2> y_range{0, 0};
  std::array<double, 2> z_range{0, 0};        // 3-D only: the layer's depth (2-D: z = 0)
  int count = 0;                              // particles wanted
  std::vector<double> number_fraction;        // per species, sums to 1
  std::array<double, 2> mean_velocity{0, 0};  // in the x-y plane (3-D: none along z)
  double sigma_m_per_s = 0;  // Gaussian fluctuation per component, z's included in 3-D
  std::uint64_t seed = 0;
  std::uint64_t event = 0;    // insertion event number: the RNG stream
  long inserted_before = 0;   // particles inserted by earlier events
  bool rebuild_lists = true;  // false: the caller inserts more before the next step
};

// Particles deleted because they left through an open boundary, counted per face.
struct RemovalCounts {
  std::array<long, 3> low{0, 0, 0};   // through the lower face of each axis
  std::array<long, 3> high{0, 0, 0};  // through the upper face
  long total() const { return low[0] + low[1] + low[2] + high[0] + high[1] + high[2]; }
};

// Where slab boundaries lie on several processes (docs/parallel.md, "Load balance"):
// equal slabs of cell rows, or moved at list rebuilds to balance the particle count or the
// measured compute time. The choice never changes the results, only who computes what.
enum class SlabBalance { equal, particles, work };

// How several processes divide the box (docs/parallel.md): slabs of cell rows along x
// (across the flow, through the periodic faces) or along y (along the flow), and how
// their boundaries move. Neither choice changes the results.
enum class SlabAxis { x = 0, y = 1 };
struct Decomposition {
  SlabAxis axis = SlabAxis::y;
  SlabBalance balance = SlabBalance::equal;
};

class SolverStepping {
 public:
  virtual ~SolverStepping() = default;

  virtual void set_particles(const HostParticles& particles) = 0;
  // Deletes escaped particles, sorts by cell and rebuilds the neighbour list now (the time
  // loop does it by itself whenever a particle has moved half the skin).
  virtual void rebuild_lists() = 0;
  virtual void advance(long steps) = 0;

  // Inserts up to request.count particles (fewer when there is no room); new ids are
  // consecutive from next_id(). Returns how many were inserted.
  virtual int insert(const InsertionRequest& request) = 0;
  // Deletes particles outside the box on open axes when setup.delete_outside is set
  // (also done at every neighbour-list rebuild); returns all deletions so far.
  virtual RemovalCounts remove_escaped() = 0;
  virtual RemovalCounts removed() const = 0;
  virtual int next_id() const = 0;

  // Several processes: the slabs' axis and how their boundaries move at list rebuilds,
  // chosen before any particle is placed. One process: nothing to divide.
  virtual void decompose(const Decomposition& decomposition) = 0;

  virtual std::size_t size() const = 0;  // the particles this process owns
  virtual long global_size() const = 0;  // on every process (collective)
  // The Verlet skin the current list was built with (m): the scene's, or with
  // SolverSetup::adaptive_skin the last choice of core/skin_model.hpp.
  virtual double skin() const = 0;
  virtual double time() const = 0;
  virtual std::string variant() const = 0;  // e.g. "2d/double/frictionless/obstacle/OpenMP"
};

}  // namespace granshock

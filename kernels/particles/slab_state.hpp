// The state of several processes as one process holds it (docs/parallel.md): beside the
// slab exchange, the host side of checkpoints and snapshots on slabs. A rank's particles
// in cell order of their reference positions (the last rebuild's sort), merged over the
// ranks by cell, are one process's order; each layer of the flat cell index across the
// slabs (snapshot_part.hpp) is one run of rows. Gathered to rank 0, with the list one
// process would hold built from the reference positions, the state is the one-process
// state, bit for bit.
#pragma once

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/communicator.hpp"
#include "core/particle_bytes.hpp"
#include "core/snapshot_part.hpp"
#include "core/solver.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/solver/state_io.hpp"

namespace granshock::slab_state {

// The cell of each owned particle's reference position: its place in the last sort.
template <class Paths, class Store, class Grid>
std::vector<int> reference_cells(const Store& p, const Grid& grid) {
  auto x_ref = host_copy<Paths>(p.x_ref);
  std::vector<int> cells(std::size_t(p.n));
  for (int i = 0; i < p.n; ++i) cells[std::size_t(i)] = grid.cell_of(x_ref, i);
  return cells;
}

// The rows by increasing cell, rows of one cell in their given order (by id, as the last
// sort left them).
inline std::vector<int> in_cell_order(const std::vector<int>& cells) {
  std::vector<int> rows(cells.size());
  std::iota(rows.begin(), rows.end(), 0);
  std::stable_sort(rows.begin(), rows.end(),
                   [&](int a, int b) { return cells[std::size_t(a)] < cells[std::size_t(b)]; });
  return rows;
}

// The particles whose cell row is the slab's.
template <class Position, class Slabs>
HostParticles mine(const HostParticles& all, const Slabs& slabs) {
  HostParticles out;
  // Spin values per particle: 1 in 2-D, 3 in 3-D (core/host_particles.hpp), or none.
  const std::size_t spins = all.size() == 0 ? 0 : all.angular_velocity.size() / all.size();
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!slabs.owns(Position(all.position[i][std::size_t(slabs.axis())]))) continue;
    out.add(all.position[i], all.velocity[i], all.species[i], all.id[i]);
    for (std::size_t c = 0; c < spins; ++c)
      out.angular_velocity.push_back(all.angular_velocity[i * spins + c]);
  }
  return out;
}

// The part of a whole state that is this slab's: the particles whose reference position
// (where the last rebuild left them) lies in it.
template <int Dim, class Position, class Slabs>
SolverState own_part(const SolverState& all, const Slabs& slabs) {
  std::vector<int> rows;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto along = Position(all.reference_position[i * Dim + std::size_t(slabs.axis())]);
    if (slabs.owns(along)) rows.push_back(int(i));
  }
  return select_particles(all, rows);
}

// A rank's part of a snapshot: its particles (`own`, in store order) in cell order and the
// rows of the file they go to.
template <class Paths, class Store, class Grid, class Slabs>
SnapshotPart snapshot_part(const HostParticles& own, const Store& p, const Grid& grid,
                           const Slabs& slabs) {
  SnapshotPart part;
  const std::vector<int> cells = reference_cells<Paths>(p, grid);
  part.particles = select_particles(own, in_cell_order(cells));
  part.rows = slabs.file_rows(cells, part.total);
  return part;
}

// The whole state on rank 0 from every rank's `local` state (its scalars and its own
// particles, in store order); the other ranks get the scalars only.
template <int Dim, class Real, class ExecSpace, class Paths, class Store, class Grid, class Box,
          class Radius, class Slabs>
SolverState gather(const SolverState& local, const Store& p, const Grid& grid, const Box& box,
                   const Radius& radius, Real skin, const Slabs& slabs, const Communicator& comm) {
  const std::vector<int> cells = reference_cells<Paths>(p, grid);
  long total = 0;
  const std::vector<FileRows> rows = gather_to_root(comm, slabs.file_rows(cells, total));
  SolverState all = select_particles(local, {});
  append_particles(comm.gather(pack_particles(select_particles(local, in_cell_order(cells))), 0),
                   all);
  if (!comm.is_root()) return all;
  all = select_particles(all, row_sources(rows, total, all.size()));
  state_io::ReferenceLists lists =
      state_io::lists_from_reference<Dim, Real, ExecSpace, Paths>(all, grid, box, radius, skin);
  for (std::size_t k = 0; k < lists.order.size(); ++k)
    if (lists.order[k] != int(k))
      throw std::logic_error("the gathered particles are out of the global cell order");
  all.neighbour_offsets = std::move(lists.offsets);
  all.neighbours = std::move(lists.neighbours);
  return all;
}

}  // namespace granshock::slab_state

// A solver's state to and from the host (checkpoints; docs/output_format.md): the particle
// arrays through the store's one list (ParticleStore::for_each_array), and what only the
// solver's own arithmetic can check about a state read back: that its reference positions
// are where a rebuild leaves them, that no particle has moved far enough since to force a
// rebuild, and that the particle order and neighbour list are exactly what sorting and
// building from those positions give (core/checkpoint_checks.hpp has the rest).
#pragma once

#include <fmt/format.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "core/checkpoint_checks.hpp"
#include "core/host_particles.hpp"
#include "core/solver_setup.hpp"
#include "core/solver_state.hpp"
#include "kernels/device/box_geometry.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/neighbours/cell_grid.hpp"
#include "kernels/neighbours/cell_sort.hpp"
#include "kernels/neighbours/verlet_list.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/population_kernels.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

namespace state_io {

// Paths: the solver's (device/host_mirror.hpp).
// The first n rows of a device View as a flat host vector (row-major).
template <class Paths, class View, class T>
void to_host(const View& view, int n, std::vector<T>& out) {
  const auto h = host_copy<Paths>(view);
  const int width = View::rank == 1 ? 1 : int(view.extent(1));
  out.resize(std::size_t(n) * width);
  for (int i = 0; i < n; ++i) {
    if constexpr (View::rank == 1) {
      out[i] = T(h(i));
    } else {
      for (int c = 0; c < width; ++c) out[std::size_t(i) * width + c] = T(h(i, c));
    }
  }
}

template <class Paths, class View, class T>
void from_host(const View& view, int n, const std::vector<T>& in, const char* what) {
  const int width = View::rank == 1 ? 1 : int(view.extent(1));
  if (in.size() != std::size_t(n) * width)
    throw std::runtime_error(std::string("checkpoint field '") + what + "' has the wrong size");
  auto h = host_mirror<Paths>(view);
  for (int i = 0; i < n; ++i) {
    if constexpr (View::rank == 1) {
      h(i) = typename View::value_type(in[i]);
    } else {
      for (int c = 0; c < width; ++c)
        h(i, c) = typename View::value_type(in[std::size_t(i) * width + c]);
    }
  }
  Kokkos::deep_copy(view, h);
}

// Every per-particle array of the store into the state, and back (an array the state may
// lack, StateArray::may_be_absent, at its rest value when it does).
template <class Paths, class Store>
void export_particles(const Store& p, SolverState& s) {
  Store::for_each_array(
      [&](auto array, const auto& view) { to_host<Paths>(view, p.n, s.*array.member); }, p);
  s.history_slots = Store::friction ? Store::history_slots : 0;
}
template <class Paths, class Store>
void import_particles(Store& p, const SolverState& s) {
  const int n = int(s.size());
  Store::for_each_array(
      [&](auto array, auto& view) {
        if (array.may_be_absent && (s.*array.member).empty()) {
          Kokkos::deep_copy(view, array.rest);
        } else {
          from_host<Paths>(view, n, s.*array.member, array.name);
        }
      },
      p);
  p.n = n;
}

// Particles given by position, velocity, species, id and (where there is spin) angular
// velocity: those arrays from `given`, every other one at its rest value (StateArray::rest),
// as for a fresh particle.
template <class Paths, class Store, int Dim>
void import_given(Store& p, const HostParticles& given) {
  SolverState s;
  const std::size_t n = given.size();
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < Dim; ++d) {
      s.position.push_back(given.position[i][std::size_t(d)]);
      s.velocity.push_back(given.velocity[i][std::size_t(d)]);
    }
  s.species = given.species;
  s.id = given.id;
  s.angular_velocity = given.angular_velocity;
  Store::for_each_array(
      [&](auto array, auto& view) {
        if ((s.*array.member).empty()) {
          Kokkos::deep_copy(view, array.rest);
        } else {
          from_host<Paths>(view, int(n), s.*array.member, array.name);
        }
      },
      p);
  p.n = int(n);
}

// The cell order and Verlet list that sorting and building from a state's reference
// positions give (as a rebuild does): what a state must hold (check_lists), and what a
// state gathered from several processes gets (StateTransfer::export_state).
struct ReferenceLists {
  std::vector<int> order;  // order[k]: the state row that comes k-th in cell order
  std::vector<int> offsets;
  std::vector<int> neighbours;
};

template <int Dim, class Real, class ExecSpace, class Paths, class RadiusView>
ReferenceLists lists_from_reference(const SolverState& s, const CellGrid<Dim, Position>& grid,
                                    const BoxGeometry<Dim, Position>& box, const RadiusView& radius,
                                    Real skin) {
  using Mem = typename ExecSpace::memory_space;
  const int n = int(s.size());
  ReferenceLists out;
  out.offsets.assign(1, 0);
  if (n == 0) return out;
  Kokkos::View<Position* [Dim], Mem> xr("reference_x", n);
  Kokkos::View<int*, Mem> species("reference_species", n), id("reference_id", n);
  auto h_xr = host_mirror<Paths>(xr);
  auto h_species = host_mirror<Paths>(species);
  auto h_id = host_mirror<Paths>(id);
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < Dim; ++d)
      h_xr(i, d) = Position(s.reference_position[std::size_t(i) * Dim + d]);
    h_species(i) = s.species[std::size_t(i)];
    h_id(i) = s.id[std::size_t(i)];
  }
  Kokkos::deep_copy(xr, h_xr);
  Kokkos::deep_copy(species, h_species);
  Kokkos::deep_copy(id, h_id);
  CellSort<Dim, Position, ExecSpace> sort;
  sort.sort(grid, xr, id, n);
  to_host<Paths>(sort.order, n, out.order);
  VerletList<Dim, Real, ExecSpace, Paths> list;
  list.build(grid, box, sort.cell_start, xr, species, radius, skin, n);
  to_host<Paths>(list.offsets, n + 1, out.offsets);
  to_host<Paths>(list.neighbours, list.total, out.neighbours);
  return out;
}

// Refuses (InvalidCheckpoint) a state whose lists this solver would not have built.
// Positions are Position (double) in every variant (device/position.hpp); the other
// arrays of a single-precision solver hold floats.
template <int Dim, class Real, class ExecSpace, class Paths, class RadiusView>
void check_lists(const SolverState& s, const CellGrid<Dim, Position>& grid,
                 const BoxGeometry<Dim, Position>& box, const EscapeTest<Dim, Position>& escape,
                 const RadiusView& radius, Real skin) {
  const int n = int(s.size());
  auto fail = [](const std::string& what) { throw InvalidCheckpoint(what); };
  if constexpr (!std::is_same_v<Real, double>) {
    for (const auto* values : {&s.velocity, &s.force, &s.angular_velocity, &s.torque,
                               &s.history_spring, &s.history_obstacle_spring})
      for (double v : *values)
        if (double(Real(v)) != v)
          fail(fmt::format("/state: {} is not a value of this single-precision solver", v));
  }
  const Real rebuild_d2 = Real(0.25) * skin * skin;  // as in ListKeeping::expired
  for (int i = 0; i < n; ++i) {
    Real d2 = 0;
    for (int d = 0; d < Dim; ++d) {
      const std::size_t k = std::size_t(i) * Dim + d;
      const Position ref = Position(s.reference_position[k]);
      const bool wrapped = box.wrap(d, ref) == ref;
      const bool kept = !escape.check[d] || (ref >= escape.lo[d] && ref < escape.hi[d]);
      if (!wrapped || !kept)
        fail(
            fmt::format("/state/reference_position[{}] = {} is outside the box on axis {}, "
                        "where a rebuild leaves none",
                        k, double(ref), d));
      const Real moved = Real(Position(s.position[k]) - ref);
      d2 += moved * moved;
    }
    if (d2 > rebuild_d2)
      fail(
          fmt::format("/state/position[{}]: particle {} is more than half the skin from its "
                      "reference position; the solver would have rebuilt its lists",
                      std::size_t(i) * Dim, s.id[std::size_t(i)]));
  }
  if (n == 0) return;
  const ReferenceLists built =
      lists_from_reference<Dim, Real, ExecSpace, Paths>(s, grid, box, radius, skin);
  for (int k = 0; k < n; ++k)
    if (built.order[std::size_t(k)] != k)
      fail(
          fmt::format("/state/id: particle {} at row {} is out of the cell order of "
                      "/state/reference_position",
                      s.id[std::size_t(k)], k));
  for (int i = 0; i <= n; ++i)
    if (built.offsets[std::size_t(i)] != s.neighbour_offsets[std::size_t(i)])
      fail(
          fmt::format("/state/neighbour_offsets[{}] = {}, but the list built from "
                      "/state/reference_position gives {}",
                      i, s.neighbour_offsets[std::size_t(i)], built.offsets[std::size_t(i)]));
  for (std::size_t k = 0; k < built.neighbours.size(); ++k)
    if (built.neighbours[k] != s.neighbours[k])
      fail(
          fmt::format("/state/neighbours[{}] = {}, but the list built from "
                      "/state/reference_position gives {}",
                      k, s.neighbours[k], built.neighbours[k]));
}

// What a solver of this variant expects of a state (core/checkpoint_checks.hpp).
template <int Dim, class Real, int HistorySlots>
SolverFit solver_fit(const SolverSetup& setup, bool friction) {
  SolverFit f;
  f.dim = Dim;
  f.history_slots = friction ? HistorySlots : 0;
  f.box = setup.box;
  f.delete_outside = setup.delete_outside;
  for (const Species& species : setup.species) f.radius.push_back(species.radius_m());
  for (const auto& row : setup.contacts.friction)
    for (double mu : row) f.max_friction = std::max(f.max_friction, mu);
  for (double mu : setup.contacts.obstacle_friction) f.max_friction = std::max(f.max_friction, mu);
  if (setup.obstacle)
    f.obstacle_distance = [o = *setup.obstacle](const double* x) {
      return Dim == 3 ? obstacle_distance_in_3d(o, x[0], x[1], x[2])
                      : obstacle_distance(o, x[0], x[1]);
    };
  double extent = 0;
  for (int d = 0; d < Dim; ++d)
    extent = std::max({extent, std::abs(setup.box.lo[d]), std::abs(setup.box.hi[d])});
  // The contact test rounds a separation (formed in double) and the radii to Real: a few
  // ulps of a contact distance, which a few ulps of the box's extent bound from above.
  f.distance_tolerance = 16 * double(std::numeric_limits<Real>::epsilon()) * extent;
  return f;
}

}  // namespace state_io

}  // namespace granshock

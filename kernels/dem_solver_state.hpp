// Export and import of a DemSolver's complete state (checkpoints). Included by
// dem_solver.hpp.
#pragma once

#include <fmt/format.h>

#include <limits>
#include <type_traits>

namespace granshock {

namespace state_detail {
// Copies the first n rows of a device View into a flat host vector (row-major).
template <class View, class T>
void to_host(const View& view, int n, std::vector<T>& out) {
  const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
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
template <class View, class T>
void from_host(const View& view, int n, const std::vector<T>& in, const char* what) {
  const int width = View::rank == 1 ? 1 : int(view.extent(1));
  if (in.size() != std::size_t(n) * width)
    throw std::runtime_error(std::string("checkpoint field '") + what + "' has the wrong size");
  auto h = Kokkos::create_mirror_view(view);
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
}  // namespace state_detail

template <class Traits, class ExecSpace>
SolverState DemSolver<Traits, ExecSpace>::export_state() const {
  using namespace state_detail;
  SolverState s;
  s.dim = Dim;
  s.step = steps_;
  s.next_id = next_id_;
  const int n = p_.n;
  to_host(p_.x, n, s.position);
  to_host(p_.v, n, s.velocity);
  to_host(p_.f, n, s.force);
  to_host(p_.species, n, s.species);
  to_host(p_.id, n, s.id);
  if constexpr (Traits::friction) {
    to_host(p_.omega, n, s.angular_velocity);
    to_host(p_.torque, n, s.torque);
    s.history_slots = ContactHistory<Dim, Real, Mem>::slots;
    to_host(history_.partner, n, s.history_partner);
    to_host(history_.spring, n, s.history_spring);
    to_host(history_.wall_spring, n, s.history_wall_spring);
  }
  to_host(x_ref_, n, s.reference_position);
  to_host(list_.offsets, n + 1, s.neighbour_offsets);
  to_host(list_.neighbours, list_.total, s.neighbours);
  s.list_builds = builds_;
  s.removed_low = removed_.low;
  s.removed_high = removed_.high;
  return s;
}

template <class Traits, class ExecSpace>
SolverFit DemSolver<Traits, ExecSpace>::fit() const {
  SolverFit f;
  f.dim = Dim;
  f.history_slots = Traits::friction ? ContactHistory<Dim, Real, Mem>::slots : 0;
  f.box = setup_.box;
  f.delete_outside = setup_.delete_outside;
  for (const Species& species : setup_.species) f.radius.push_back(species.radius_m());
  for (const auto& row : setup_.contacts.friction)
    for (double mu : row) f.max_friction = std::max(f.max_friction, mu);
  for (double mu : setup_.contacts.wall_friction) f.max_friction = std::max(f.max_friction, mu);
  f.obstacle = setup_.obstacle;
  double extent = 0;
  for (int d = 0; d < Dim; ++d)
    extent = std::max({extent, std::abs(setup_.box.lo[d]), std::abs(setup_.box.hi[d])});
  f.distance_tolerance = 16 * double(std::numeric_limits<Real>::epsilon()) * extent;
  return f;
}

// What only this solver's own arithmetic can tell (core/checkpoint_checks.hpp has the
// rest): the reference positions are where the last rebuild left them, no particle has
// moved far enough since to force a rebuild, and the particle order and neighbour list
// are exactly what sorting and building from the reference positions give.
template <class Traits, class ExecSpace>
void DemSolver<Traits, ExecSpace>::check_lists(const SolverState& s) const {
  const int n = int(s.size());
  auto fail = [](const std::string& what) { throw InvalidCheckpoint(what); };
  if constexpr (!std::is_same_v<Real, double>) {
    for (const auto* values : {&s.position, &s.velocity, &s.force, &s.angular_velocity, &s.torque,
                               &s.history_spring, &s.history_wall_spring, &s.reference_position})
      for (double v : *values)
        if (double(Real(v)) != v)
          fail(fmt::format("/state: {} is not a value of this single-precision solver", v));
  }
  const Real rebuild_d2 = Real(0.25) * skin_ * skin_;  // as in advance()
  Kokkos::View<Real* [Dim], Mem> xr("check_x_ref", std::max(n, 1));
  Kokkos::View<int*, Mem> species("check_species", std::max(n, 1)), id("check_id", std::max(n, 1));
  auto h_xr = Kokkos::create_mirror_view(xr);
  auto h_species = Kokkos::create_mirror_view(species);
  auto h_id = Kokkos::create_mirror_view(id);
  for (int i = 0; i < n; ++i) {
    Real d2 = 0;
    for (int d = 0; d < Dim; ++d) {
      const std::size_t k = std::size_t(i) * Dim + d;
      const Real ref = Real(s.reference_position[k]);
      const bool wrapped = box_.wrap(d, ref) == ref;
      const bool kept =
          !escape_.test.check[d] || (ref >= escape_.test.lo[d] && ref < escape_.test.hi[d]);
      if (!wrapped || !kept)
        fail(
            fmt::format("/state/reference_position[{}] = {} is outside the box on axis {}, "
                        "where a rebuild leaves none",
                        k, double(ref), d));
      h_xr(i, d) = ref;
      const Real moved = Real(s.position[k]) - ref;
      d2 += moved * moved;
    }
    if (d2 > rebuild_d2)
      fail(
          fmt::format("/state/position[{}]: particle {} is more than half the skin from its "
                      "reference position; the solver would have rebuilt its lists",
                      std::size_t(i) * Dim, s.id[std::size_t(i)]));
    h_species(i) = s.species[std::size_t(i)];
    h_id(i) = s.id[std::size_t(i)];
  }
  if (n == 0) return;
  Kokkos::deep_copy(xr, h_xr);
  Kokkos::deep_copy(species, h_species);
  Kokkos::deep_copy(id, h_id);
  CellSort<Dim, Real, ExecSpace> sort;
  sort.sort(grid_, xr, id, n);
  const auto order = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sort.order);
  for (int k = 0; k < n; ++k)
    if (order(k) != k)
      fail(
          fmt::format("/state/id: particle {} at row {} is out of the cell order of "
                      "/state/reference_position",
                      s.id[std::size_t(k)], k));
  VerletList<Dim, Real, ExecSpace> list;
  list.build(grid_, box_, sort.cell_start, xr, species, table_.radius, skin_, n);
  const auto offsets = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.offsets);
  const auto neighbours = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.neighbours);
  for (int i = 0; i <= n; ++i)
    if (offsets(i) != s.neighbour_offsets[std::size_t(i)])
      fail(
          fmt::format("/state/neighbour_offsets[{}] = {}, but the list built from "
                      "/state/reference_position gives {}",
                      i, s.neighbour_offsets[std::size_t(i)], offsets(i)));
  for (int k = 0; k < list.total; ++k)
    if (neighbours(k) != s.neighbours[std::size_t(k)])
      fail(
          fmt::format("/state/neighbours[{}] = {}, but the list built from "
                      "/state/reference_position gives {}",
                      k, s.neighbours[std::size_t(k)], neighbours(k)));
}

template <class Traits, class ExecSpace>
void DemSolver<Traits, ExecSpace>::import_state(const SolverState& s) {
  using namespace state_detail;
  const SolverFit f = fit();
  check_state(s);  // as read_checkpoint did: the checks below rely on it
  check_fit(s, f);
  check_lists(s);
  check_contacts(s, f);
  const int n = int(s.size());
  if (n > p_.capacity()) allocate(n + n / 4);
  from_host(p_.x, n, s.position, "position");
  from_host(p_.v, n, s.velocity, "velocity");
  from_host(p_.f, n, s.force, "force");
  from_host(p_.species, n, s.species, "species");
  from_host(p_.id, n, s.id, "id");
  if constexpr (Traits::friction) {
    from_host(p_.omega, n, s.angular_velocity, "angular_velocity");
    from_host(p_.torque, n, s.torque, "torque");
    from_host(history_.partner, n, s.history_partner, "history_partner");
    from_host(history_.spring, n, s.history_spring, "history_spring");
    from_host(history_.wall_spring, n, s.history_wall_spring, "history_wall_spring");
  }
  from_host(x_ref_, n, s.reference_position, "reference_position");
  list_.assign(s.neighbour_offsets, s.neighbours);
  p_.n = n;
  steps_ = s.step;
  next_id_ = s.next_id;
  builds_ = s.list_builds;
  removed_.low = s.removed_low;
  removed_.high = s.removed_high;
}

}  // namespace granshock

// Export and import of a DemSolver's complete state (checkpoints). Included by
// dem_solver.hpp.
#pragma once

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
void DemSolver<Traits, ExecSpace>::import_state(const SolverState& s) {
  using namespace state_detail;
  if (s.dim != Dim) throw std::runtime_error("checkpoint dimension does not match the scene");
  const int n = int(s.size());
  if (n > p_.capacity()) allocate(n + n / 4);
  from_host(p_.x, n, s.position, "position");
  from_host(p_.v, n, s.velocity, "velocity");
  from_host(p_.f, n, s.force, "force");
  from_host(p_.species, n, s.species, "species");
  from_host(p_.id, n, s.id, "id");
  if constexpr (Traits::friction) {
    if (s.history_slots != ContactHistory<Dim, Real, Mem>::slots)
      throw std::runtime_error("checkpoint contact history does not match this build");
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

// Tangential spring history for frictional scenes (never allocated without friction).
// Each particle keeps a few slots keyed by the partner's global id, so the history
// survives neighbour-list rebuilds and particle reordering without remapping. Only the
// thread handling particle i touches i's slots (full neighbour list), so no atomics.
#pragma once

#include <Kokkos_Core.hpp>

namespace granshock {

template <int Dim, class Real, class MemSpace>
struct ContactHistory {
  static constexpr int slots = Dim == 2 ? 8 : 16;  // > the contacts a sphere can have

  Kokkos::View<int* [slots], MemSpace> partner;         // global id, -1 when free
  Kokkos::View<Real * [slots * Dim], MemSpace> spring;  // xi per slot
  Kokkos::View<Real* [Dim], MemSpace> wall_spring;      // xi against the obstacle
  Kokkos::View<int, MemSpace> overflow;                 // set when a particle runs out of slots

  void allocate(int capacity) {
    partner = decltype(partner)("history_partner", capacity);
    spring = decltype(spring)("history_spring", capacity);
    wall_spring = decltype(wall_spring)("history_wall_spring", capacity);
    overflow = decltype(overflow)("history_overflow");
    Kokkos::deep_copy(partner, -1);
  }
};

}  // namespace granshock

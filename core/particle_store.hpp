// Particle storage on the device: a structure of arrays of Kokkos Views.
// Owned particles occupy [0, n); the Views are allocated with spare capacity so that
// particles can be inserted and removed (and ghosts appended after the owned ones)
// without a reallocation each step. Positions and velocities are View<Real*[Dim]>:
// contiguous components per particle on the host (LayoutRight), one array per
// component on a GPU (LayoutLeft), each the coalesced layout for its backend.
#pragma once

#include <Kokkos_Core.hpp>
#include <string>

namespace granshock {

template <int Dim, class Real, class MemSpace>
struct ParticleStore {
  using VectorView = Kokkos::View<Real* [Dim], MemSpace>;
  using ScalarView = Kokkos::View<Real*, MemSpace>;
  using IntView = Kokkos::View<int*, MemSpace>;

  VectorView x, v, f;
  ScalarView omega, torque;  // rotation about z; allocated only when friction can spin
  IntView species;
  IntView id;  // global id, never reused within a run
  int n = 0;   // owned particles

  int capacity() const { return int(x.extent(0)); }
  bool has_rotation() const { return omega.extent(0) > 0; }

  void allocate(int cap, bool rotation, const std::string& prefix = "") {
    x = VectorView(prefix + "x", cap);
    v = VectorView(prefix + "v", cap);
    f = VectorView(prefix + "f", cap);
    omega = ScalarView(prefix + "omega", rotation ? cap : 0);
    torque = ScalarView(prefix + "torque", rotation ? cap : 0);
    species = IntView(prefix + "species", cap);
    id = IntView(prefix + "id", cap);
  }
};

}  // namespace granshock

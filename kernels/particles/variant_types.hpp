// The types every kernel of one compiled variant works in (docs/design.md, "The variant
// table"), derived once from the Variant (kernels/solver/variant.hpp) and the execution
// space: a kernel takes the ones it needs from here instead of spelling them again.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/particles/particle_store.hpp"

namespace granshock {

template <class V, class ExecSpace>
struct VariantTypes {
  static constexpr int Dim = V::dim;
  using Real = typename V::real;
  using Model = typename V::model;  // the contact law
  using Mem = typename ExecSpace::memory_space;
  using Policy = Kokkos::RangePolicy<ExecSpace>;
  using Store = ParticleStore<Dim, Real, Mem, V::friction>;
  // The obstacle's geometry in this dimension and precision (kernels/models/obstacle_body.hpp).
  using Obstacle = typename V::obstacle::template Geometry<Dim, Real>;
  // Positions, the box, cells and the skin displacement are in Position (double) in every
  // variant; the rest in Real (device/position.hpp; docs/design.md, "Particles").
  using Position = typename Store::Position;
};

}  // namespace granshock

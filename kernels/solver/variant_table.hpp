// The variant table (docs/design.md, "The variant table"): every combination of dimension,
// contact law, friction and obstacle shape that granshock compiles, for each precision and
// backend. The lists below are the whole table; make_solver_variant walks their product
// for one dimension, skips the combinations a Variant does not compile (Variant::compiled:
// 3-D in double precision only), and builds the DemSolver whose Variant matches the scene. Adding a
// contact law is one entry in ContactLaws (kernels/models/models.hpp), an obstacle shape one entry
// in ObstacleShapes (models/obstacle_shapes.hpp), which adds no variant; adding a backend is one
// file variants_<backend>_<precision>[_3d].cpp and a line in solver_dispatch.cpp.
#pragma once

#include <memory>

#include "core/communicator.hpp"
#include "core/solver.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/models/models.hpp"
#include "kernels/solver/variant.hpp"

namespace granshock {

template <int... D>
struct DimList {};

using CompiledDimensions = DimList<2, 3>;  // one translation unit per dimension
using CompiledModels = ContactLaws;        // kernels/models/models.hpp
// Every shape is one ObstacleBody (kernels/models/obstacle_body.hpp): shapes add no variant.
using CompiledObstacles = TypeList<NoObstacle, ObstacleBody>;

// Calls f(Variant{}) for every compiled variant of precision Real.
template <class Real, class F, int... Dims, class... Models, class... Obstacles>
void for_each_variant(F&& f, DimList<Dims...>, TypeList<Models...>, TypeList<Obstacles...>) {
  auto with_dim = [&](auto dim) {
    auto with_model = [&](auto model) {
      auto with_obstacle = [&](auto obstacle) {
        using M = decltype(model);
        using O = decltype(obstacle);
        constexpr int D = decltype(dim)::value;
        using Frictionless = Variant<D, Real, M, false, O>;
        using Frictional = Variant<D, Real, M, true, O>;
        if constexpr (Frictionless::compiled) f(Frictionless{});
        if constexpr (Frictional::compiled) f(Frictional{});
      };
      (with_obstacle(Obstacles{}), ...);
    };
    (with_model(Models{}), ...);
  };
  (with_dim(std::integral_constant<int, Dims>{}), ...);
}

// The solver of the compiled variant that matches the scene, for one dimension, precision
// and backend (instantiated in variants_<backend>_<precision>[_3d].cpp, which compile in
// parallel), on the backend's own host or device paths (device/backends.hpp).
template <int Dim, class Real, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
std::unique_ptr<Solver> make_solver_variant(const SolverSetup& setup, std::size_t capacity,
                                            const Communicator& comm);

}  // namespace granshock

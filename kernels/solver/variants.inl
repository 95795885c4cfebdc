// The definition of make_solver_variant; included by the variants_*.cpp files (and by a
// test that builds the other paths, tests/unit/solver_on_paths.cpp).
#include "core/user_error.hpp"
#include "kernels/solver/dem_solver.hpp"
#include "kernels/solver/variant_table.hpp"

namespace granshock {

template <int Dim, class Real, class ExecSpace, class Paths>
std::unique_ptr<Solver> make_solver_variant(const SolverSetup& setup, std::size_t capacity,
                                            const Communicator& comm) {
  std::unique_ptr<Solver> solver;
  for_each_variant<Real>(
      [&](auto variant) {
        using V = decltype(variant);
        if (!solver && V::matches(setup))
          solver = std::make_unique<DemSolver<V, ExecSpace, Paths>>(setup, capacity, comm);
      },
      DimList<Dim>{}, CompiledModels{}, CompiledObstacles{});
  if (!solver)
    throw UserError(
        "no compiled solver variant for this scene (dim = " + std::to_string(setup.dim) +
        ", contact model " + to_string(setup.contacts.model) +
        (setup.contacts.has_friction() ? ", friction" : ", no friction") +
        "); docs/design.md lists the variants");
  return solver;
}

}  // namespace granshock

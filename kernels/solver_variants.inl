// Definition of make_solver_variant; included only by the solver_variants_*.cpp files.
#include "dem_solver.hpp"
#include "solver_variants.hpp"
#include "user_error.hpp"

namespace granshock {

template <class Real, class ExecSpace>
std::unique_ptr<Solver> make_solver_variant(const SystemSetup& setup, std::size_t capacity) {
  if (setup.dim != 2)
    throw UserError("dim = " + std::to_string(setup.dim) +
                    ": only quasi-2-D scenes (dim = 2) are supported so far");
  const bool friction = setup.contacts.has_friction();
  const bool obstacle = setup.obstacle.has_value();
  if (friction && obstacle)
    return std::make_unique<DemSolver<SceneTraits<2, Real, true, true>, ExecSpace>>(setup,
                                                                                    capacity);
  if (friction)
    return std::make_unique<DemSolver<SceneTraits<2, Real, true, false>, ExecSpace>>(setup,
                                                                                     capacity);
  if (obstacle)
    return std::make_unique<DemSolver<SceneTraits<2, Real, false, true>, ExecSpace>>(setup,
                                                                                     capacity);
  return std::make_unique<DemSolver<SceneTraits<2, Real, false, false>, ExecSpace>>(setup,
                                                                                    capacity);
}

}  // namespace granshock

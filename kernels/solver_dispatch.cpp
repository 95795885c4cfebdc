// The one place where a scene's needs select a compiled kernel variant
// (DESIGN.md section 5): precision and backend here, dimension, friction and obstacle
// in make_solver_variant. Chosen once, at start-up; nothing is re-decided per pair.
#include "backends.hpp"
#include "solver.hpp"
#include "solver_variants.hpp"

namespace granshock {

std::unique_ptr<Solver> make_solver(const SystemSetup& setup, std::size_t capacity,
                                    Backend backend) {
  const bool single = setup.precision == Precision::single;
#if GRANSHOCK_SEPARATE_SERIAL
  if (backend == Backend::serial)
    return single ? make_solver_variant<float, Kokkos::Serial>(setup, capacity)
                  : make_solver_variant<double, Kokkos::Serial>(setup, capacity);
#else
  (void)backend;  // the default execution space is the only one
#endif
  return single ? make_solver_variant<float, Kokkos::DefaultExecutionSpace>(setup, capacity)
                : make_solver_variant<double, Kokkos::DefaultExecutionSpace>(setup, capacity);
}

}  // namespace granshock

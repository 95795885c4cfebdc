// make_solver: the one place where a scene's needs select a compiled kernel variant
// (docs/design.md, "The variant table"): precision and backend here, dimension, contact
// law, friction and obstacle shape in make_solver_variant (variant_table.hpp). Chosen
// once, at start-up; nothing is re-decided per pair.
#include <type_traits>

#include "core/solver.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/solver/variant_table.hpp"

namespace granshock {

std::unique_ptr<Solver> make_solver(const SolverSetup& setup, std::size_t capacity, Backend backend,
                                    const Communicator* comm) {
  const Communicator& c = comm ? *comm : SingleProcess::instance();
  const bool single = setup.precision == Precision::single_precision;
#if GRANSHOCK_SEPARATE_SERIAL
  if (backend == Backend::serial)
    return single ? make_solver_variant<float, Kokkos::Serial>(setup, capacity, c)
                  : make_solver_variant<double, Kokkos::Serial>(setup, capacity, c);
#else
  (void)backend;  // the default execution space is the only one
#endif
  return single ? make_solver_variant<float, Kokkos::DefaultExecutionSpace>(setup, capacity, c)
                : make_solver_variant<double, Kokkos::DefaultExecutionSpace>(setup, capacity, c);
}

int switchable_host_threads() {
#if GRANSHOCK_SEPARATE_SERIAL
  using Default = Kokkos::DefaultExecutionSpace;
  return std::is_same_v<Default::memory_space, Kokkos::HostSpace> ? Default().concurrency() : 0;
#else
  return 0;
#endif
}

}  // namespace granshock

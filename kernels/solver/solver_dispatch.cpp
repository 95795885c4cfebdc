// make_solver: the one place where a scene's needs select a compiled kernel variant
// (docs/design.md, "The variant table"): dimension, precision and backend here, contact
// law, friction and obstacle shape in make_solver_variant (variant_table.hpp). Chosen
// once, at start-up; nothing is re-decided per pair.
#include <string>
#include <type_traits>

#include "core/solver.hpp"
#include "core/user_error.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/solver/variant_table.hpp"

namespace granshock {

namespace {

template <class ExecSpace>
std::unique_ptr<Solver> make_on(const SolverSetup& setup, std::size_t capacity,
                                const Communicator& c) {
  const bool single = setup.precision == Precision::single_precision;
  if (setup.dim == 3) {
    if (single)
      throw UserError(
          "3-D scenes run in double precision only (docs/design.md, \"The variant table\")");
    return make_solver_variant<3, double, ExecSpace>(setup, capacity, c);
  }
  if (setup.dim != 2)
    throw UserError("dimension " + std::to_string(setup.dim) + ": granshock runs 2 or 3");
  return single ? make_solver_variant<2, float, ExecSpace>(setup, capacity, c)
                : make_solver_variant<2, double, ExecSpace>(setup, capacity, c);
}

}  // namespace

std::unique_ptr<Solver> make_solver(const SolverSetup& setup, std::size_t capacity, Backend backend,
                                    const Communicator* comm) {
  const Communicator& c = comm ? *comm : SingleProcess::instance();
#if GRANSHOCK_SEPARATE_SERIAL
  if (backend == Backend::serial) return make_on<Kokkos::Serial>(setup, capacity, c);
#else
  (void)backend;  // the default execution space is the only one
#endif
  return make_on<Kokkos::DefaultExecutionSpace>(setup, capacity, c);
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

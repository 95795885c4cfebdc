// The other paths' solver for tests/unit/solver_on_paths.hpp. The build's own paths come
// from make_solver; the other ones are instantiated here, on the host backend, for the
// variants the comparison tests run (double precision, Hertz), so that every build of
// the tests compiles four more kernel variants, not the whole table.
#include "solver_on_paths.hpp"

#include <stdexcept>

#include "kernels/device/backends.hpp"
#include "kernels/solver/dem_solver.hpp"
#include "kernels/solver/variant_table.hpp"

namespace granshock::test {

namespace {

constexpr bool own_host = uses_host_paths<Kokkos::DefaultExecutionSpace>();

#if GRANSHOCK_SEPARATE_SERIAL
constexpr bool serial_takes_the_other = uses_host_paths<Kokkos::Serial>() != own_host;
#else
constexpr bool serial_takes_the_other = false;
#endif

std::unique_ptr<Solver> other_paths_solver(const SolverSetup& s, std::size_t capacity) {
  if constexpr (serial_takes_the_other) {
    return make_solver(s, capacity, Backend::serial);
  } else {
    using Space = Kokkos::DefaultHostExecutionSpace;
    using Other = KernelPaths<!own_host>;
    std::unique_ptr<Solver> solver;
    for_each_variant<double>(
        [&](auto variant) {
          using V = decltype(variant);
          if (!solver && V::matches(s))
            solver = std::make_unique<DemSolver<V, Space, Other>>(s, capacity,
                                                                  SingleProcess::instance());
        },
        DimList<2>{}, TypeList<HertzModel>{}, CompiledObstacles{});
    if (!solver)
      throw std::logic_error(
          "make_solver_on_paths: the other paths are built for 2-D, double precision and Hertz "
          "contacts only");
    return solver;
  }
}

}  // namespace

const char* to_string(Paths p) {
  return p == Paths::host ? "host" : "device";
}

Paths default_paths() {
  return own_host ? Paths::host : Paths::device;
}

std::unique_ptr<Solver> make_solver_on_paths(const SolverSetup& setup, std::size_t capacity,
                                             Paths paths) {
  if (paths == default_paths()) return make_solver(setup, capacity, Backend::default_space);
  return other_paths_solver(setup, capacity);
}

}  // namespace granshock::test

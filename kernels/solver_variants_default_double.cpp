#include "solver_variants.inl"

namespace granshock {
template std::unique_ptr<Solver> make_solver_variant<double, Kokkos::DefaultExecutionSpace>(
    const SystemSetup&, std::size_t);
}  // namespace granshock

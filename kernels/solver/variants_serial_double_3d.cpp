#include "kernels/device/backends.hpp"
#if GRANSHOCK_SEPARATE_SERIAL
#include "kernels/solver/variants.inl"

namespace granshock {
template std::unique_ptr<Solver> make_solver_variant<3, double, Kokkos::Serial>(
    const SolverSetup&, std::size_t, const Communicator&);
}  // namespace granshock
#endif

#include "backends.hpp"
#if GRANSHOCK_SEPARATE_SERIAL
#include "solver_variants.inl"

namespace granshock {
template std::unique_ptr<Solver> make_solver_variant<float, Kokkos::Serial>(const SystemSetup&,
                                                                            std::size_t);
}  // namespace granshock
#endif

// The compiled solver variants for one (precision, execution space): chooses dimension,
// friction and obstacle from the scene. Explicitly instantiated in solver_variants_*.cpp
// (one file per precision and backend, so they compile in parallel).
#pragma once

#include <memory>

#include "solver.hpp"

namespace granshock {

template <class Real, class ExecSpace>
std::unique_ptr<Solver> make_solver_variant(const SystemSetup& setup, std::size_t capacity);

}  // namespace granshock

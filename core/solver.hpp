// The interface every compiled solver variant offers to apps and tests. A variant is
// one instantiation of the kernels for what a scene needs (dimension, precision,
// friction, obstacle); make_solver picks it once, at start-up. The interface is four
// parts, each in its own header, so that code which only steps, samples, moves state or
// measures can say so in its signature.
#pragma once

#include <cstddef>
#include <memory>

#include "core/communicator.hpp"
#include "core/solver_sampling.hpp"
#include "core/solver_setup.hpp"
#include "core/solver_state_io.hpp"
#include "core/solver_statistics.hpp"
#include "core/solver_stepping.hpp"

namespace granshock {

class Solver : public SolverStepping,
               public SolverSampling,
               public SolverStateIO,
               public SolverStatistics {
 public:
  ~Solver() override = default;
};

enum class Backend { default_space, serial };

// The one place where a scene's needs select a compiled kernel variant
// (kernels/solver/variant_table.hpp). `comm` carries the global reductions
// (communicator.hpp); by default one process owns everything.
std::unique_ptr<Solver> make_solver(const SolverSetup& setup, std::size_t capacity,
                                    Backend backend = Backend::default_space,
                                    const Communicator* comm = nullptr);

// The default backend's threads when it runs on the host's threads beside a separate
// one-thread backend, so that a run may move between the two
// (cases/bow_shock/backend_switch.hpp); 0 otherwise (a GPU, or Serial alone).
int switchable_host_threads();

}  // namespace granshock

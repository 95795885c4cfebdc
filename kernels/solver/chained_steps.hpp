// Chained steps: device paths' time loop without a host read per step (docs/design.md,
// "The solver"; docs/cuda.md, "Launches per step"). The host loop (step_loop.hpp) asks
// after every fused step whether the list has expired, which on a GPU is a fence and a
// device-to-host read of the step's reduction per step. Here the rebuild watch
// (neighbours/rebuild_watch.hpp) lives on the device while steps are queued: each step is
// two launches, the fused pass (fused_step.hpp) reducing into a device value, and a
// one-thread kernel that feeds that value to the watch and asks the host loop's question
// for the next step. When the answer needs the host (a list build, or an exact
// displacement pass after a bound that failed) the watch stops the chain, and the steps
// still queued do nothing. The host reads the state once per chain: how many steps ran,
// and the watch as they left it, the same watch the host loop would hold, since every
// decision is the host's arithmetic on the same values in double. The particles'
// arithmetic is the fused pass's, so the trajectory is bitwise the host loop's
// (tests/unit/test_backend_agreement.cpp, `KernelPaths`, `ChainedSteps`).
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/launch_counter.hpp"
#include "kernels/neighbours/rebuild_watch.hpp"
#include "kernels/solver/fused_step.hpp"

namespace granshock {

// The device's copy of the step loop's rebuild decision, while a chain runs.
struct ChainState {
  RebuildWatch watch;
  long done = 0;     // steps taken since the host last wrote this state
  int stopped = 0;   // the host must act before the next step: the chain's rest does nothing
  int by_speed = 0;  // how the next step reports: by speed, or the exact displacement
};

// The host's state for the chain, written on the device.
template <class Mem>
struct SetChainState {
  Kokkos::View<ChainState, Mem> state;
  ChainState value;
  KOKKOS_INLINE_FUNCTION void operator()(const int) const { state() = value; }
};

// One step of a chain: the fused pass, unless the chain has stopped, reporting as the
// device's watch says (Max into the device value `reported`; the launch's name ends in
// "->device", launch_counter.hpp).
template <class V, class ExecSpace, class Paths>
struct ChainedFusedStep {
  using Kernel = FusedStepKernel<V, ExecSpace, Paths>;
  using Real = typename Kernel::Real;
  using Mem = typename Kernel::Mem;

  Kernel kernel;
  Kokkos::View<const ChainState, Mem> state;

  KOKKOS_INLINE_FUNCTION void operator()(const int run, Real& worst) const {
    const ChainState& c = state();
    if (c.stopped) return;
    kernel.advance_run(run, c.by_speed != 0, worst);
  }
};

// After a step (or the first half that starts advance()): the step's report to the watch,
// then the host loop's question before the next step (ListKeeping::expired): proved valid
// by the bound, or exactly measured and still inside the skin, and the chain goes on;
// otherwise the host acts. One thread.
template <class Real, class Mem>
struct ChainWatch {
  Kokkos::View<ChainState, Mem> state;
  Kokkos::View<const Real, Mem> reported;
  Real rebuild_d2;        // (skin/2)^2, in Real as the host compares it
  bool exact_list_check;  // SolverSetup: every step reports its exact displacement
  bool after_step;        // false after the first half, which is not a step of the loop

  KOKKOS_INLINE_FUNCTION void operator()(const int) const {
    ChainState& c = state();
    if (c.stopped) return;
    const double value = double(reported());
    if (after_step && c.by_speed) {
      c.watch.drifted(value);
    } else {
      c.watch.measured(value);
    }
    if (after_step) ++c.done;
    const bool expired_or_unknown = c.watch.exact_known() ? Real(c.watch.exact_d2()) > rebuild_d2
                                                          : !c.watch.bound_proves_valid();
    if (expired_or_unknown) {
      c.stopped = 1;
      return;
    }
    c.by_speed = !exact_list_check && c.watch.next_drift_by_speed();
  }
};

}  // namespace granshock

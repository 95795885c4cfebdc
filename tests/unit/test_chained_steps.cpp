// What chained steps (kernels/solver/chained_steps.hpp) cost beyond arithmetic, against
// the kernel sequence they are written to launch: on device paths and one process, a call
// of advance(n) writes the chain's state, runs the first half and its watch, then per
// step the fused pass and the watch, then the closing pass (forces and second half in
// one, fused_step.hpp): 2 n + 2 kernels, and one read by the host per chain (launch_counter.hpp,
// "host_reads"). Host paths, for comparison, read every step's reduction where the scene is too
// large for many steps per region.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "kernels/device/launch_counter.hpp"
#include "solver_on_paths.hpp"

using namespace granshock;

namespace {

// A dilute gas so slow that no list expires within the call: no list build, no exact
// pass, so every launch and read is the stepping's own.
struct SlowGas {
  SolverSetup setup = paper_mixture(0.9);
  HostParticles particles;
  SlowGas() {
    setup.dt = 5e-7;
    GasSpec spec;
    spec.particles = 400;
    spec.area_fraction = 0.1;
    spec.sigma_m_per_s = 1e-3;  // 0.5 nm per step against a skin of 0.3 mm
    size_periodic_box(setup, spec);
    particles = make_homogeneous_gas(setup, spec);
  }
};

struct Counted {
  LaunchCounts counts;
  long builds = 0, exact_checks = 0;
};

Counted count_advance(const SolverSetup& setup, const HostParticles& particles, long steps,
                      test::Paths paths) {
  auto solver = test::make_solver_on_paths(setup, particles.size(), paths);
  solver->set_particles(particles);
  solver->advance(2);  // the first list build and the step buffers, outside the count
  Kokkos::fence();
  const long builds = solver->list_builds(), exact = solver->exact_list_checks();
  LaunchCounter counter;
  EXPECT_TRUE(counter.start()) << "a profiling tool is loaded (KOKKOS_TOOLS_LIBS)?";
  solver->advance(steps);
  Counted c;
  c.counts = counter.stop();
  c.builds = solver->list_builds() - builds;
  c.exact_checks = solver->exact_list_checks() - exact;
  return c;
}

}  // namespace

TEST(ChainedSteps, TwoLaunchesPerStepAndOneHostReadPerChain) {
  const SlowGas gas;
  const long steps = 200;
  const Counted one_chain = count_advance(gas.setup, gas.particles, steps, test::Paths::device);
  ASSERT_EQ(one_chain.builds, 0);
  ASSERT_EQ(one_chain.exact_checks, 0);
  EXPECT_EQ(one_chain.counts.kernels, std::uint64_t(2 * steps + 2));
  EXPECT_EQ(one_chain.counts.reductions, std::uint64_t(steps));  // first half, 199 passes
  EXPECT_EQ(one_chain.counts.host_reads, 1u);                    // the chain's state, once

  // Chains of at most 10 steps: the 199 fused steps are 20 chains, 20 reads.
  SolverSetup short_chains = gas.setup;
  short_chains.steps_per_region = 10;
  const Counted chains = count_advance(short_chains, gas.particles, steps, test::Paths::device);
  EXPECT_EQ(chains.counts.kernels, std::uint64_t(2 * steps + 2));  // no write between
  EXPECT_EQ(chains.counts.host_reads, 20u);
}

TEST(ChainedSteps, TheHostLoopReadsEveryStep) {
  // One region per step (host paths' many-step regions off, as for a large scene): the
  // first half and each fused step are a reduction into a host value.
  SlowGas gas;
  gas.setup.steps_per_region = 1;
  const long steps = 200;
  const Counted host = count_advance(gas.setup, gas.particles, steps, test::Paths::host);
  ASSERT_EQ(host.builds, 0);
  EXPECT_EQ(host.counts.kernels, std::uint64_t(steps + 1));  // first half, 199, closing
  EXPECT_EQ(host.counts.host_reads, std::uint64_t(steps));
}

// A solver on Serial (one thread, the backend a run moves to beside a busy process:
// docs/benchmarks.md, "A busy machine") must launch nothing on the OpenMP threads while
// it steps. Kokkos fills and copies host Views on the default host space unless told
// otherwise; beside a busy process each such OpenMP region waited for a descheduled
// thread, and one thread inside a switched run went at 0.4 of a one-thread run's rate.
// The kernels therefore fill, copy and allocate on their own space (device/space_alloc.hpp).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cstdint>
#include <string>
#include <type_traits>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "kernels/device/backends.hpp"

using namespace granshock;

namespace {

// Every Kokkos kernel launched while the callback is set: its execution space's id.
struct LaunchLog {
  static inline std::uint32_t openmp_id = 0;
  static inline long on_openmp = 0;
  static inline std::string first_on_openmp;
  static inline bool probing = false;
};

void record_launch(const char* name, std::uint32_t device_id, std::uint64_t* kernel_id) {
  *kernel_id = 0;
  if (LaunchLog::probing) {
    LaunchLog::openmp_id = device_id;
    return;
  }
  if (device_id != LaunchLog::openmp_id) return;
  if (LaunchLog::on_openmp++ == 0) LaunchLog::first_on_openmp = name;
}

TEST(OneThreadSolver, StepsWithoutOpenMPRegions) {
  if constexpr (!GRANSHOCK_SEPARATE_SERIAL ||
                !std::is_same_v<Kokkos::DefaultHostExecutionSpace::memory_space,
                                Kokkos::HostSpace> ||
                std::is_same_v<Kokkos::DefaultHostExecutionSpace, Kokkos::Serial>) {
    GTEST_SKIP() << "needs Serial beside a threaded default host backend (OpenMP)";
  } else {
    SolverSetup s = paper_mixture(0.5);
    s.dt = 5e-8;
    GasSpec spec;
    spec.particles = 6000;  // past Kokkos' 80 KB threshold for a threaded host copy
    spec.area_fraction = 0.3;
    spec.sigma_m_per_s = 2.0;
    size_periodic_box(s, spec);
    auto solver = make_solver(s, spec.particles, Backend::serial);
    solver->set_particles(make_homogeneous_gas(s, spec));
    solver->advance(20);  // the first steps size the solver's arrays

    // The id Kokkos gives the default host space's kernels: from a fill on that space.
    Kokkos::View<double*, Kokkos::HostSpace> probe("probe", 16);
    Kokkos::Tools::Experimental::set_begin_parallel_for_callback(record_launch);
    LaunchLog::probing = true;
    Kokkos::deep_copy(Kokkos::DefaultHostExecutionSpace(), probe, 1.0);
    LaunchLog::probing = false;
    const long builds = solver->list_builds();
    solver->advance(3000);
    Kokkos::Tools::Experimental::set_begin_parallel_for_callback(nullptr);

    EXPECT_GT(solver->list_builds() - builds, 2) << "the steps must rebuild the lists";
    EXPECT_EQ(LaunchLog::on_openmp, 0)
        << "kernels on the OpenMP threads while a Serial solver stepped, the first: "
        << LaunchLog::first_on_openmp;
  }
}

}  // namespace

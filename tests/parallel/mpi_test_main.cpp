// GoogleTest entry point for the tests that run under an MPI launcher (ctest starts them
// with mpirun): MPI, then Kokkos, started once for the program, as granshock's main does.
#include <gtest/gtest.h>

#include <cstdio>

#include "kernels/device/kokkos_runtime.hpp"
#include "parallel/mpi_runtime.hpp"

namespace {

// A fatal failure (a failed ASSERT, an exception) on one rank leaves its test early while
// the other ranks wait for it in the test's next collective operation: the job would hang
// until ctest's timeout. Such a failure ends every rank at once, after saying where.
class EndJobOnFatalFailure : public ::testing::EmptyTestEventListener {
 public:
  explicit EndJobOnFatalFailure(const granshock::MpiRuntime& mpi) : mpi_(mpi) {}
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.fatally_failed()) return;
    std::fprintf(stderr, "rank %d: fatal failure at %s:%d: %s\nending every rank of the job\n",
                 mpi_.rank(), result.file_name() ? result.file_name() : "(unknown file)",
                 result.line_number(), result.summary());
    std::fflush(stderr);
    mpi_.abort(1);
  }

 private:
  const granshock::MpiRuntime& mpi_;
};

}  // namespace

int main(int argc, char** argv) {
  granshock::MpiRuntime mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  granshock::KokkosRuntime kokkos(argc, argv);
  // Only rank 0 prints GoogleTest's report; a failure on any rank still fails the run
  // through its exit code.
  auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
  if (mpi.rank() != 0) delete listeners.Release(listeners.default_result_printer());
  if (mpi.size() > 1) listeners.Append(new EndJobOnFatalFailure(mpi));
  return RUN_ALL_TESTS();
}

// The MPI test harness itself (mpi_test_main.cpp): a fatal failure on one rank only must
// end the job instead of leaving the other ranks waiting in a collective operation. Run
// on purpose by mpi.fatal_failure_on_one_rank_ends_the_job (disabled otherwise: it fails).
#include <gtest/gtest.h>

#include <stdexcept>

#include "parallel/mpi_communicator.hpp"

using namespace granshock;

TEST(MpiHarness, DISABLED_ExceptionOnOneRankEndsTheJob) {
  const MpiCommunicator comm;
  if (comm.rank() == 1) throw std::runtime_error("rank 1 alone fails");
  // The others wait here for rank 1, which never comes.
  EXPECT_EQ(comm.sum(1L), long(comm.size()));
}

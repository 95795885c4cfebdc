// MpiCommunicator (parallel/mpi_communicator.hpp) under mpirun: every reduction against
// its value computed in closed form from the rank numbers, on every rank.
#include <gtest/gtest.h>

#include "mpi_communicator.hpp"
#include "mpi_runtime.hpp"

using namespace granshock;

TEST(MpiCommunicator, StartedByTheLauncher) {
  EXPECT_TRUE(MpiRuntime::launched_by_mpi());
  const MpiCommunicator comm;
  EXPECT_GE(comm.size(), 2) << "ctest runs this program on several processes";
  EXPECT_GE(comm.rank(), 0);
  EXPECT_LT(comm.rank(), comm.size());
}

TEST(MpiCommunicator, ReductionsOverEveryRank) {
  const MpiCommunicator comm;
  const int r = comm.rank(), n = comm.size();
  EXPECT_EQ(comm.max(double(r) * 1.5), (n - 1) * 1.5);
  EXPECT_EQ(comm.sum(double(r + 1)), n * (n + 1) / 2.0);
  EXPECT_EQ(comm.sum(long(r) * 1000000000L), 1000000000L * n * (n - 1) / 2);
  EXPECT_TRUE(comm.any(r == n - 1));
  EXPECT_FALSE(comm.any(false));
}

TEST(MpiCommunicator, SumInPlaceAddsEveryRanksArray) {
  const MpiCommunicator comm;
  const int r = comm.rank(), n = comm.size();
  std::vector<double> values(1000);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = double(k) * (r + 1);
  comm.sum_in_place(values);
  for (std::size_t k = 0; k < values.size(); ++k)
    ASSERT_EQ(values[k], double(k) * n * (n + 1) / 2) << "element " << k;
}

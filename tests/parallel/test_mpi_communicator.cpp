// MpiCommunicator (parallel/mpi_communicator.hpp) under mpirun: every reduction and gather
// against its value computed in closed form from the rank numbers, on every rank; and the
// agreement on a failure (core/failure_agreement.hpp).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/failure_agreement.hpp"
#include "parallel/mpi_communicator.hpp"
#include "parallel/mpi_runtime.hpp"

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

namespace {

// Rank r sends r + 1 bytes of value r: the result is every rank's bytes in rank order.
std::vector<char> bytes_of_every_rank(int n) {
  std::vector<char> expected;
  for (int k = 0; k < n; ++k) expected.insert(expected.end(), std::size_t(k + 1), char(k));
  return expected;
}

}  // namespace

TEST(MpiCommunicator, GatherConcatenatesInRankOrderOnTheRootOnly) {
  const MpiCommunicator comm;
  const int r = comm.rank(), n = comm.size();
  const std::vector<char> mine(std::size_t(r + 1), char(r));
  const std::vector<char> gathered = comm.gather(mine, 0);
  if (r == 0) {
    EXPECT_EQ(gathered, bytes_of_every_rank(n));
  } else {
    EXPECT_TRUE(gathered.empty());
  }
  EXPECT_EQ(comm.all_gather(mine), bytes_of_every_rank(n));
  // A rank with nothing to send (an empty slab) takes part all the same.
  const std::vector<char> some = r == 1 ? std::vector<char>() : mine;
  std::vector<char> expected = bytes_of_every_rank(n);
  expected.erase(expected.begin() + 1, expected.begin() + 3);  // rank 1's two bytes
  EXPECT_EQ(comm.all_gather(some), expected);
}

// gather_to_root (core/communicator.hpp): typed values, one or several per rank (rank r
// sends r values r, none from rank 0), concatenated in rank order on rank 0.
TEST(MpiCommunicator, GatherToRootKeepsTypedValuesInRankOrder) {
  const MpiCommunicator comm;
  const int r = comm.rank(), n = comm.size();
  const std::vector<long> one = gather_to_root(comm, long(10 * r));
  const std::vector<double> several = gather_to_root(comm, std::vector<double>(std::size_t(r), r));
  std::vector<long> one_expected;
  std::vector<double> several_expected;
  for (int k = 0; k < n; ++k) {
    one_expected.push_back(10 * k);
    several_expected.insert(several_expected.end(), std::size_t(k), double(k));
  }
  EXPECT_EQ(one, r == 0 ? one_expected : std::vector<long>());
  EXPECT_EQ(several, r == 0 ? several_expected : std::vector<double>());
}

// core/failure_agreement.hpp: a step that fails on rank 1 alone.
TEST(FailureAgreement, TheLowestFailingRankSpeaksTheOthersLeaveQuietly) {
  const MpiCommunicator comm;
  const int r = comm.rank();
  failure_agreed() = false;
  EXPECT_NO_THROW(agree_on_failure(comm, [] {}));
  EXPECT_FALSE(failure_agreed());
  const auto fail_on = [&](int failing) {
    return [&comm, failing] {
      if (comm.rank() >= failing) throw std::runtime_error("rank " + std::to_string(comm.rank()));
    };
  };
  try {
    agree_on_failure(comm, fail_on(1));
    FAIL() << "rank " << r << " went on after rank 1 failed";
  } catch (const PeerFailed&) {
    EXPECT_NE(r, 1) << "rank 1 failed first: it says why";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(r, 1);
    EXPECT_STREQ(e.what(), "rank 1");
  }
  EXPECT_TRUE(failure_agreed());
  failure_agreed() = false;
}

// Rank r sends r + 1 bytes of value 10 r down and r + 2 of value 10 r + 1 up, on a ring
// (periodic) and on a line (open ends); each rank checks what came from each side.
TEST(MpiCommunicator, NeighbourExchangeOnARingAndALine) {
  const MpiCommunicator mpi;
  const Communicator& comm = mpi;  // as the solver calls it (the defaults are the base's)
  const int r = comm.rank(), n = comm.size();
  const auto down_of = [](int k) { return std::vector<char>(std::size_t(k + 1), char(10 * k)); };
  const auto up_of = [](int k) { return std::vector<char>(std::size_t(k + 2), char(10 * k + 1)); };
  const int below = (r - 1 + n) % n, above = (r + 1) % n;
  const NeighbourBytes ring = comm.exchange_with_neighbours(down_of(r), below, up_of(r), above);
  EXPECT_EQ(ring.lower, up_of(below)) << "from below comes what it sent up";
  EXPECT_EQ(ring.upper, down_of(above));
  // Known sizes (the halo between rebuilds): no size messages, the same bytes.
  const ExpectedBytes sizes{long(up_of(below).size()), long(down_of(above).size())};
  const NeighbourBytes known =
      comm.exchange_with_neighbours(down_of(r), below, up_of(r), above, sizes);
  EXPECT_EQ(known.lower, ring.lower);
  EXPECT_EQ(known.upper, ring.upper);
  // A line: rank 0 has nothing below, the last rank nothing above.
  const int lower = r > 0 ? r - 1 : Communicator::kNone;
  const int upper = r + 1 < n ? r + 1 : Communicator::kNone;
  const NeighbourBytes line = comm.exchange_with_neighbours(down_of(r), lower, up_of(r), upper);
  EXPECT_EQ(line.lower, r > 0 ? up_of(r - 1) : std::vector<char>());
  EXPECT_EQ(line.upper, r + 1 < n ? down_of(r + 1) : std::vector<char>());
}

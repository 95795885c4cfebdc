// The solver on several processes (kernels/particles/slab_exchange.hpp), under mpirun: a
// dense periodic gas, advanced on slabs with migration, ghosts and the halo, against the
// same gas advanced by one process on every rank. Each rank compares the particles it owns
// with the one-process run's particles of the same id, bitwise (docs/parallel.md).
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "homogeneous_gas.hpp"
#include "mpi_communicator.hpp"
#include "solver.hpp"

using namespace granshock;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST(DecomposedSolver, DenseGasIsBitwiseTheSameAsOneProcess) {
  const MpiCommunicator comm;
  SolverSetup setup = paper_mixture(0.5);
  // phi = 0.3 at 2 m/s: about 1.3 contacts per particle, and particles cross slab faces
  // many times over 8000 steps (3.2 d travelled at the mean speed).
  const GasSpec spec{2000, 0.3, 2.0, 11};
  size_periodic_box(setup, spec);
  setup.dt = 1e-7;  // about t_c/20 at the fastest impacts of this gas
  const HostParticles gas = make_homogeneous_gas(setup, spec);

  const auto one = make_solver(setup, gas.size());  // one process, on this rank
  const auto slabs = make_solver(setup, gas.size(), Backend::default_space, &comm);
  one->set_particles(gas);
  slabs->set_particles(gas);
  EXPECT_EQ(comm.sum(long(slabs->size())), long(gas.size()));
  for (int chunk = 0; chunk < 4; ++chunk) {
    one->advance(2000);
    slabs->advance(2000);
  }
  EXPECT_GT(slabs->list_builds(), 10);

  const HostParticles all = one->particles(), mine = slabs->particles();
  EXPECT_EQ(comm.sum(long(mine.size())), long(all.size())) << "a particle was lost or doubled";
  std::map<int, std::size_t> index;
  for (std::size_t k = 0; k < all.size(); ++k) index[all.id[k]] = k;
  long differing = 0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const std::size_t r = index.at(mine.id[k]);
    for (int d = 0; d < 2; ++d)
      if (!same_bits(mine.position[k][d], all.position[r][d]) ||
          !same_bits(mine.velocity[k][d], all.velocity[r][d]))
        ++differing;
  }
  EXPECT_EQ(comm.sum(differing), 0L) << "components differing from one process (all ranks)";
}

// An open y axis with the gas in its lower half only: the upper slabs start empty (as the
// wake of the obstacle nearly is), particles leave through the open faces and are deleted
// by the rank that owns them, and the rest is bitwise as in one process.
TEST(DecomposedSolver, OpenAxisWithEmptySlabsIsBitwiseTheSameAsOneProcess) {
  const MpiCommunicator comm;
  SolverSetup setup = paper_mixture(0.5);
  const GasSpec spec{1000, 0.3, 2.0, 5};
  size_periodic_box(setup, spec);
  const HostParticles gas = make_homogeneous_gas(setup, spec);
  // The same gas in a box twice as long and open along y: nothing above its middle.
  setup.box.hi[1] = setup.box.lo[1] + 2 * setup.box.length(1);
  setup.box.periodic[1] = false;
  setup.delete_outside = true;
  setup.dt = 1e-7;

  const auto one = make_solver(setup, gas.size());
  const auto slabs = make_solver(setup, gas.size(), Backend::default_space, &comm);
  one->set_particles(gas);
  slabs->set_particles(gas);
  if (comm.size() >= 3) {
    // The top slab holds nothing at the start.
    EXPECT_EQ(comm.sum(comm.rank() == comm.size() - 1 ? long(slabs->size()) : 0L), 0L);
  }
  for (int chunk = 0; chunk < 4; ++chunk) {
    one->advance(2000);
    slabs->advance(2000);
  }
  const HostParticles all = one->particles(), mine = slabs->particles();
  EXPECT_LT(all.size(), gas.size()) << "some particles should have left through y = 0";
  EXPECT_EQ(comm.sum(long(mine.size())), long(all.size()));
  std::map<int, std::size_t> index;
  for (std::size_t k = 0; k < all.size(); ++k) index[all.id[k]] = k;
  long differing = 0, unknown = 0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const auto it = index.find(mine.id[k]);
    if (it == index.end()) {
      ++unknown;
      continue;
    }
    for (int d = 0; d < 2; ++d)
      if (!same_bits(mine.position[k][d], all.position[it->second][d]) ||
          !same_bits(mine.velocity[k][d], all.velocity[it->second][d]))
        ++differing;
  }
  EXPECT_EQ(comm.sum(unknown), 0L) << "particles kept that one process deleted";
  EXPECT_EQ(comm.sum(differing), 0L) << "components differing from one process (all ranks)";
}

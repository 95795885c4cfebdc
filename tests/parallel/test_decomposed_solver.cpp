// The solver on several processes (kernels/particles/slab_exchange.hpp), under mpirun: a
// dense periodic gas, advanced on slabs with migration, ghosts and the halo, against the
// same gas advanced by one process on every rank. Each rank compares the particles it owns
// with the one-process run's particles of the same id, bitwise (docs/parallel.md). Every
// case runs on slabs along y and along x (where the ghost rows interleave by cell).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "cases/gas/homogeneous_gas.hpp"
#include "core/solver.hpp"
#include "parallel/mpi_communicator.hpp"

using namespace granshock;

namespace {

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

class DecomposedSolver : public ::testing::TestWithParam<SlabAxis> {
 protected:
  // A solver on slabs along the test's axis (one process: the plain solver).
  std::unique_ptr<Solver> on_slabs(const SolverSetup& setup, std::size_t capacity,
                                   const Communicator& comm) const {
    auto solver = make_solver(setup, capacity, Backend::default_space, &comm);
    Decomposition d;
    d.axis = GetParam();
    solver->decompose(d);
    return solver;
  }
  void expect_dense_gas_bitwise(bool adaptive_skin, int dim = 2) const;
};

}  // namespace

INSTANTIATE_TEST_SUITE_P(SlabsAlong, DecomposedSolver, ::testing::Values(SlabAxis::y, SlabAxis::x),
                         [](const ::testing::TestParamInfo<SlabAxis>& axis) {
                           return std::string(axis.param == SlabAxis::x ? "x" : "y");
                         });

// With an adaptive skin every rank must pick the same skin at the same builds (counts
// summed over ranks), or the lists, and so the sums, would differ from one process's.
// In 3-D the spheres (10^3 = 1000) have friction (mu = 0.4) and start spinning (three
// components each, handed to each slab with its particle), and their spins are compared
// too; they travel 0.6 d over 3000 steps (about a tenth of them cross a slab face), and
// the slabs' boundary layers are a range of storage per grid row and z-layer.
void DecomposedSolver::expect_dense_gas_bitwise(bool adaptive_skin, int dim) const {
  const MpiCommunicator comm;
  SolverSetup setup = paper_mixture(0.5);
  setup.adaptive_skin = adaptive_skin;
  setup.dim = dim;
  if (dim == 3) setup.contacts = ContactSettings::uniform(2, 0.5, 0.4);
  // phi = 0.3 at 2 m/s: about 1.3 contacts per particle, and particles cross slab faces
  // many times over 8000 steps (3.2 d travelled at the mean speed).
  const GasSpec spec{dim == 3 ? 1000 : 2000, 0.3, 2.0, 11};
  size_periodic_box(setup, spec);
  setup.dt = 1e-7;  // about t_c/20 at the fastest impacts of this gas
  HostParticles gas = make_homogeneous_gas(setup, spec);
  if (dim == 3)
    for (std::size_t k = 0; k < 3 * gas.size(); ++k)
      gas.angular_velocity.push_back(1000.0 * std::sin(double(k)));  // rad/s: v ~ r w / 2

  const auto one = make_solver(setup, gas.size());  // one process, on this rank
  const auto slabs = on_slabs(setup, gas.size(), comm);
  one->set_particles(gas);
  slabs->set_particles(gas);
  EXPECT_EQ(comm.sum(long(slabs->size())), long(gas.size()));
  for (int chunk = 0; chunk < 4; ++chunk) {
    one->advance(dim == 3 ? 750 : 2000);
    slabs->advance(dim == 3 ? 750 : 2000);
  }
  EXPECT_GT(slabs->list_builds(), 10);
  if (adaptive_skin) {
    EXPECT_LT(slabs->skin(), setup.skin()) << "the skin never adapted";
  }
  EXPECT_EQ(slabs->skin(), one->skin());

  const HostParticles all = one->particles(), mine = slabs->particles();
  EXPECT_EQ(comm.sum(long(mine.size())), long(all.size())) << "a particle was lost or doubled";
  std::map<int, std::size_t> index;
  for (std::size_t k = 0; k < all.size(); ++k) index[all.id[k]] = k;
  long differing = 0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const std::size_t r = index.at(mine.id[k]);
    for (int d = 0; d < dim; ++d)
      if (!same_bits(mine.position[k][d], all.position[r][d]) ||
          !same_bits(mine.velocity[k][d], all.velocity[r][d]))
        ++differing;
    const std::size_t spins = mine.angular_velocity.size() / mine.size();
    for (std::size_t c = 0; c < spins; ++c)
      if (!same_bits(mine.angular_velocity[k * spins + c], all.angular_velocity[r * spins + c]))
        ++differing;
  }
  if (dim == 3) {
    EXPECT_EQ(all.angular_velocity.size(), 3 * all.size());
    double spin = 0;
    for (double w : all.angular_velocity) spin += std::abs(w);
    EXPECT_GT(spin, 0) << "friction never turned a sphere";
  }
  EXPECT_EQ(comm.sum(differing), 0L) << "components differing from one process (all ranks)";
}

TEST_P(DecomposedSolver, DenseGasIsBitwiseTheSameAsOneProcess) {
  expect_dense_gas_bitwise(false);
}

TEST_P(DecomposedSolver, DenseGasWithAdaptiveSkinIsBitwiseTheSameAsOneProcess) {
  expect_dense_gas_bitwise(true);
}

TEST_P(DecomposedSolver, DenseFrictionalGasIn3dIsBitwiseTheSameAsOneProcess) {
  expect_dense_gas_bitwise(false, 3);
}

// An open y axis with the gas in its lower half only: the upper slabs along y start empty
// (as the wake of the obstacle nearly is), particles leave through the open faces and are
// deleted by the rank that owns them, and the rest is bitwise as in one process.
TEST_P(DecomposedSolver, OpenAxisWithEmptySlabsIsBitwiseTheSameAsOneProcess) {
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
  const auto slabs = on_slabs(setup, gas.size(), comm);
  one->set_particles(gas);
  slabs->set_particles(gas);
  if (GetParam() == SlabAxis::y && comm.size() >= 3) {
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

namespace {

// The arrays of two states that differ bit for bit (the scalars too), by name, with the
// count of differing entries: empty when they are the same.
std::string differing_entries(const SolverState& a, const SolverState& b) {
  std::string out;
  const auto count = [&](const char* name, const auto& x, const auto& y) {
    if (x.size() != y.size()) {
      out += std::string(name) + ": " + std::to_string(x.size()) + " entries against " +
             std::to_string(y.size()) + "; ";
      return;
    }
    long differing = 0;
    for (std::size_t k = 0; k < x.size(); ++k)
      if (std::memcmp(&x[k], &y[k], sizeof x[k]) != 0) ++differing;
    if (differing > 0) out += std::string(name) + ": " + std::to_string(differing) + " differ; ";
  };
  count("position", a.position, b.position);
  count("velocity", a.velocity, b.velocity);
  count("force", a.force, b.force);
  count("angular_velocity", a.angular_velocity, b.angular_velocity);
  count("torque", a.torque, b.torque);
  count("species", a.species, b.species);
  count("id", a.id, b.id);
  count("history_partner", a.history_partner, b.history_partner);
  count("history_spring", a.history_spring, b.history_spring);
  count("history_obstacle_spring", a.history_obstacle_spring, b.history_obstacle_spring);
  count("reference_position", a.reference_position, b.reference_position);
  count("neighbour_offsets", a.neighbour_offsets, b.neighbour_offsets);
  count("neighbours", a.neighbours, b.neighbours);
  if (a.step != b.step || a.next_id != b.next_id || a.list_builds != b.list_builds ||
      a.removed_low != b.removed_low || a.removed_high != b.removed_high)
    out += "scalars; ";
  return out;
}

InsertionRequest inflow_event(const SolverSetup& setup, std::uint64_t event, long before) {
  InsertionRequest rq;
  rq.x_range = {setup.box.lo[0], setup.box.hi[0]};
  // The lower 60 % of the box: on 2 to 4 ranks the strip spans several slabs.
  rq.y_range = {setup.box.lo[1], setup.box.lo[1] + 0.6 * setup.box.length(1)};
  rq.count = 150;
  rq.number_fraction = {0.5, 0.5};
  rq.mean_velocity = {0, 2.0};
  rq.sigma_m_per_s = 0.5;
  rq.seed = 3;
  rq.event = event;
  rq.inserted_before = before;
  return rq;
}

}  // namespace

// Insertion events whose strip spans several slabs, with friction (contact histories),
// then the checkpoint state: rank 0's gathered state is the one-process state bit for bit
// (order, lists and all), and a solver on slabs that imports it goes on as one process.
TEST_P(DecomposedSolver, InsertionAndCheckpointStateAreThoseOfOneProcess) {
  const MpiCommunicator comm;
  SolverSetup setup = paper_mixture(0.5);
  setup.contacts = ContactSettings::uniform(2, 0.5, 0.5);
  const GasSpec spec{600, 0.15, 2.0, 9};
  size_periodic_box(setup, spec);
  HostParticles gas = make_homogeneous_gas(setup, spec);
  setup.box.hi[1] = setup.box.lo[1] + 2 * setup.box.length(1);
  setup.box.periodic[1] = false;
  setup.delete_outside = true;
  setup.dt = 1e-7;

  const auto one = make_solver(setup, 2000);
  const auto slabs = on_slabs(setup, 2000, comm);
  one->set_particles(gas);
  slabs->set_particles(gas);
  long inserted = 0;
  for (std::uint64_t event = 0; event < 3; ++event) {
    const InsertionRequest rq = inflow_event(setup, event, inserted);
    const int placed_one = one->insert(rq);
    const int placed = slabs->insert(rq);
    EXPECT_EQ(placed, placed_one) << "event " << event << ", rank " << comm.rank();
    EXPECT_GT(placed, 0);
    inserted += placed;
    one->advance(1500);
    slabs->advance(1500);
  }
  EXPECT_EQ(slabs->global_size(), long(one->size()));
  EXPECT_EQ(slabs->removed().total(), one->removed().total());
  EXPECT_GT(one->removed().total(), 0) << "particles should have left through y = 0";

  const SolverState state = one->export_state();
  const SolverState gathered = slabs->export_state();
  if (comm.rank() == 0) {
    EXPECT_EQ(gathered.size(), state.size());
    EXPECT_EQ(differing_entries(gathered, state), "") << "rank 0's gathered state";
  } else {
    EXPECT_EQ(gathered.size(), 0U) << "only rank 0 gathers";
  }

  const auto resumed = on_slabs(setup, 2000, comm);
  resumed->import_state(state);
  EXPECT_EQ(resumed->global_size(), long(state.size()));
  one->advance(3000);
  resumed->advance(3000);
  const SolverState after = one->export_state(), after_resumed = resumed->export_state();
  if (comm.rank() == 0) {
    EXPECT_EQ(differing_entries(after_resumed, after), "");
  }
  // The snapshot parts at their file rows: one process's order.
  const SnapshotPart part = resumed->snapshot_part();
  EXPECT_EQ(part.total, long(one->size()));
  const HostParticles all = gather_snapshot(comm, part);
  if (comm.rank() == 0) {
    EXPECT_EQ(all.id, one->particles().id) << "the parts at their rows: one process's order";
  }
  const long runs = comm.sum(long(part.rows.size()));
  if (GetParam() == SlabAxis::x) {
    EXPECT_GT(runs, 2L * comm.size()) << "along x, a run per grid row";
  }
}

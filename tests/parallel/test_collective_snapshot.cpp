// Collective snapshot output (RunFile::append_snapshot_collectively, docs/parallel.md,
// "Output") under mpirun: every process writes its own rows of each frame at once through
// parallel HDF5, and the file holds, bit for bit, what one process writes with the whole
// frame: rows interleaved between processes, a process with no rows, a frame smaller than
// the file's particle capacity (its padding) and one spanning several chunks.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/user_error.hpp"
#include "io/run_file.hpp"
#include "io_test_support.hpp"
#include "parallel/mpi_communicator.hpp"

using namespace granshock;

namespace {

// Frame f's rows dealt out in runs of 1 to 5 (and one long run) to the ranks in turn; on
// frame 1 the last rank gets none.
SnapshotPart part_of(const HostParticles& whole, int frame, int rank, int ranks) {
  SnapshotPart part;
  part.total = long(whole.size());
  long row = 0;
  for (int k = 0; row < part.total; ++k) {
    int owner = (k + frame) % ranks;
    if (frame == 1 && owner == ranks - 1) owner = 0;
    const long length = std::min(part.total - row, k == 3 ? 17000L : 1L + (7L * k + frame) % 5);
    if (owner == rank) {
      part.rows.push_back({row, length});
      for (long i = row; i < row + length; ++i)
        part.particles.add(whole.position[std::size_t(i)], whole.velocity[std::size_t(i)],
                           whole.species[std::size_t(i)], whole.id[std::size_t(i)]);
    }
    row += length;
  }
  return part;
}

// One directory for every rank: rank 0 makes it, the others learn its name.
std::filesystem::path shared_directory(const MpiCommunicator& comm) {
  const long pid = gather_to_all(comm, std::vector<long>{long(getpid())}).at(0);
  const auto dir =
      std::filesystem::temp_directory_path() / ("granshock_collective_" + std::to_string(pid));
  if (comm.is_root()) std::filesystem::create_directories(dir);
  comm.max(0.0);  // a barrier: the directory exists before anyone writes
  return dir;
}

template <class T>
bool same_bytes(const test::Array<T>& a, const test::Array<T>& b) {
  return a.shape == b.shape && a.values.size() == b.values.size() &&
         std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(T)) == 0;
}

}  // namespace

TEST(CollectiveSnapshot, FileIsBitwiseWhatOneProcessWrites) {
  const MpiCommunicator comm;
  const std::filesystem::path dir = shared_directory(comm);
  const std::filesystem::path collective = dir / "collective.h5", serial = dir / "serial.h5";
  // Frame sizes: a small one, a smaller one (padding to the capacity), one over a chunk.
  const std::vector<int> sizes{40, 25, 20000};
  std::optional<RunFile> root_file;
  if (comm.is_root()) {
    root_file.emplace(RunFile::create(collective, "as given", "resolved", 2));
    RunFile one = RunFile::create(serial, "as given", "resolved", 2);
    for (int f = 0; f < int(sizes.size()); ++f)
      one.append_snapshot(10L * (f + 1), 0.5 * (f + 1), test::random_particles(sizes[f]));
  }
  for (int f = 0; f < int(sizes.size()); ++f) {
    const HostParticles whole = test::random_particles(sizes[std::size_t(f)]);
    RunFile::append_snapshot_collectively(collective, comm.native(), 10L * (f + 1), 0.5 * (f + 1),
                                          part_of(whole, f, comm.rank(), comm.size()), root_file);
    EXPECT_EQ(root_file.has_value(), comm.is_root()) << "rank 0 holds the file again";
  }
  if (comm.is_root()) {
    root_file.reset();
    const std::string all = "/particles/all/";
    for (const char* name : {"position", "velocity"}) {
      EXPECT_TRUE(same_bytes(test::read_array<double>(collective, all + name + "/value"),
                             test::read_array<double>(serial, all + name + "/value")))
          << name;
      EXPECT_TRUE(same_bytes(test::read_array<double>(collective, all + name + "/time"),
                             test::read_array<double>(serial, all + name + "/time")))
          << name;
    }
    for (const char* name : {"species", "id"})
      EXPECT_TRUE(same_bytes(test::read_array<int>(collective, all + name + "/value"),
                             test::read_array<int>(serial, all + name + "/value")))
          << name;
    for (const char* name : {"position/step", "id/step", "count/step", "count/value"})
      EXPECT_TRUE(same_bytes(test::read_array<long>(collective, all + name),
                             test::read_array<long>(serial, all + name)))
          << name;
    EXPECT_EQ(RunFile::open_read_only(collective).frames().size(), sizes.size());
  }
  comm.max(0.0);
  if (comm.is_root()) std::filesystem::remove_all(dir);
}

// A step that does not follow the last frame's is refused on every process alike (no
// process left waiting in a collective call), and the file keeps its frames.
TEST(CollectiveSnapshot, StepNotAfterTheLastIsRefusedEverywhere) {
  const MpiCommunicator comm;
  const std::filesystem::path dir = shared_directory(comm);
  const std::filesystem::path path = dir / "run.h5";
  std::optional<RunFile> root_file;
  if (comm.is_root()) root_file.emplace(RunFile::create(path, "as given", "resolved", 2));
  const HostParticles whole = test::random_particles(30);
  RunFile::append_snapshot_collectively(path, comm.native(), 100, 1.0,
                                        part_of(whole, 0, comm.rank(), comm.size()), root_file);
  bool refused = false;
  try {
    RunFile::append_snapshot_collectively(path, comm.native(), 100, 1.0,
                                          part_of(whole, 0, comm.rank(), comm.size()), root_file);
  } catch (const std::invalid_argument& e) {
    refused = std::string(e.what()).find("does not follow") != std::string::npos;
  }
  EXPECT_TRUE(comm.all(refused)) << "refused on every rank";
  if (comm.is_root()) {
    root_file.reset();
    EXPECT_EQ(RunFile::open_read_only(path).frames().size(), 1U);
  }
  comm.max(0.0);
  if (comm.is_root()) std::filesystem::remove_all(dir);
}

// A run file from before collective output (its snapshot chunks made as written, which
// parallel HDF5 cannot do) is refused on every process with what to do instead.
TEST(CollectiveSnapshot, FileFromBeforeCollectiveOutputIsRefusedEverywhere) {
  const MpiCommunicator comm;
  const std::filesystem::path dir = shared_directory(comm);
  const std::filesystem::path path = dir / "run.h5";
  std::optional<RunFile> root_file;
  if (comm.is_root()) {
    RunFile::create(path, "as given", "resolved", 2);
    // Replace the positions by a dataset of the old kind: chunks made when written.
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(H5Ldelete(f, "/particles/all/position/value", H5P_DEFAULT), 0);
    const hsize_t dims[3] = {0, 0, 2}, max_dims[3] = {H5S_UNLIMITED, H5S_UNLIMITED, 2},
                  chunk[3] = {1, 16384, 2};
    const hid_t space = H5Screate_simple(3, dims, max_dims);
    const hid_t props = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(props, 3, chunk);
    H5Pset_alloc_time(props, H5D_ALLOC_TIME_INCR);
    const hid_t set = H5Dcreate2(f, "/particles/all/position/value", H5T_IEEE_F64LE, space,
                                 H5P_DEFAULT, props, H5P_DEFAULT);
    ASSERT_GE(set, 0);
    H5Dclose(set);
    H5Pclose(props);
    H5Sclose(space);
    H5Fclose(f);
    root_file.emplace(RunFile::open_for_append(path));
  }
  std::string message;
  try {
    RunFile::append_snapshot_collectively(
        path, comm.native(), 10, 0.5,
        part_of(test::random_particles(30), 0, comm.rank(), comm.size()), root_file);
  } catch (const UserError& e) {
    message = e.what();
  }
  EXPECT_TRUE(comm.all(message.find("written by an earlier granshock") != std::string::npos &&
                       message.find("resume this run on one process") != std::string::npos))
      << message;
  comm.max(0.0);
  if (comm.is_root()) std::filesystem::remove_all(dir);
}

// The gathered way (gather_snapshot, core/snapshot_part.hpp): every part at its rows on
// rank 0; rows that fill a row twice are a defect, said as such.
TEST(CollectiveSnapshot, GatherPutsEveryPartAtItsRows) {
  const MpiCommunicator comm;
  const HostParticles whole = test::random_particles(500);
  const HostParticles gathered = gather_snapshot(comm, part_of(whole, 2, comm.rank(), comm.size()));
  if (comm.is_root()) {
    EXPECT_EQ(gathered.id, whole.id);
    EXPECT_EQ(gathered.position, whole.position);
  } else {
    EXPECT_EQ(gathered.size(), 0U);
  }
  // Every rank claims rows [0, its count): rows filled several times, none past them.
  SnapshotPart overlapping = part_of(whole, 2, comm.rank(), comm.size());
  const long mine = long(overlapping.particles.size());
  overlapping.rows = {{0, mine}};
  bool refused = false;
  try {
    gather_snapshot(comm, overlapping);
  } catch (const std::logic_error&) {
    refused = true;
  }
  EXPECT_EQ(refused, comm.is_root()) << "rank 0 places the rows";
}

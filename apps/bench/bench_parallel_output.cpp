// granshock_bench_parallel_output: is gathering a snapshot to rank 0 faster than writing it
// collectively with parallel HDF5 at granshock's sizes (docs/scaling.md, "Output")?
//
// Under `mpirun -np N`, a snapshot of P particles split evenly over the ranks (position
// and velocity, 3 doubles each; species and id, one int each: what run.h5 stores per
// particle) is written to a new HDF5 file, REPEATS times each way, the two interleaved:
//   gathered:   MPI_Gatherv of each array to rank 0, which writes the file alone (what
//               granshock does);
//   collective: every rank opens the file through MPI-IO (H5Pset_fapl_mpio) and writes
//               its rows of each dataset in one collective transfer.
// A time is from a barrier before the first call to a barrier after the file is closed,
// file creation included. Then the same frames appended to run.h5 files as granshock
// writes them (RunFile: chunked, compressed), a frame per repeat each way: gathered and
// appended by rank 0, against RunFile::append_snapshot_collectively (the file closed on
// rank 0, written by every rank, reopened). Prints one Markdown row per particle count: the medians
// and their ratio (collective / gathered: above 1, gathering is faster).
//
// Both write contiguous datasets of a fresh file; run.h5 appends to chunked datasets, which
// both would do alike. Usage:
//   mpirun -np N granshock_bench_parallel_output [--particles 31600,3200000] [--repeats 7]
//     [--dir DIR]
#include <hdf5.h>
#include <mpi.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/hdf5_handle.hpp"
#include "io/run_file.hpp"

namespace {

using granshock::HostParticles;
using granshock::RunFile;
using granshock::SnapshotPart;
using granshock::h5::checked;
using granshock::h5::Handle;

// This rank's share of a snapshot: rows [first, first + count) of P.
struct Share {
  long total = 0, first = 0, count = 0;
  std::vector<double> position, velocity;  // count x 3
  std::vector<int> species, id;
};

Share make_share(long total, int rank, int ranks) {
  Share s;
  s.total = total;
  s.first = total * rank / ranks;
  s.count = total * (rank + 1) / ranks - s.first;
  for (long i = 0; i < s.count; ++i) {
    const double x = double(s.first + i);
    s.position.insert(s.position.end(), {x * 1e-3, x * 2e-3, 0.0});
    s.velocity.insert(s.velocity.end(), {1.0 / (1 + x), -x * 1e-6, 0.0});
    s.species.push_back(int((s.first + i) % 2));
    s.id.push_back(int(s.first + i));
  }
  return s;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error(what + " failed");
}

// A dataset of total x width values of `type` in `file`.
Handle create_dataset(hid_t file, const char* name, hid_t type, long total, int width) {
  const std::array<hsize_t, 2> dims{hsize_t(total), hsize_t(width)};
  const Handle space = checked(H5Screate_simple(width == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose,
                               "H5Screate_simple");
  return checked(H5Dcreate2(file, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Dclose, std::string("H5Dcreate2 ") + name);
}

// Every rank's share, concatenated in rank order, on rank 0 (empty elsewhere).
struct Gathered {
  std::vector<double> position, velocity;
  std::vector<int> species, id;
};

Gathered gather_to_rank_0(const Share& s, int rank, int ranks) {
  std::vector<int> counts(static_cast<std::size_t>(ranks), 0);
  const int mine = int(s.count);
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  const auto gather = [&](const auto& values, MPI_Datatype type, int width) {
    std::vector<std::decay_t<decltype(values[0])>> all(rank == 0 ? std::size_t(s.total * width)
                                                                 : 0);
    std::vector<int> c(counts), o(counts.size(), 0);
    int at = 0;
    for (int r = 0; r < ranks; ++r) {
      c[std::size_t(r)] = counts[std::size_t(r)] * width;
      o[std::size_t(r)] = at;
      at += c[std::size_t(r)];
    }
    MPI_Gatherv(values.data(), mine * width, type, all.data(), c.data(), o.data(), type, 0,
                MPI_COMM_WORLD);
    return all;
  };
  return {gather(s.position, MPI_DOUBLE, 3), gather(s.velocity, MPI_DOUBLE, 3),
          gather(s.species, MPI_INT, 1), gather(s.id, MPI_INT, 1)};
}

// Rank 0 gathers every array and writes the file alone; `gather_seconds` receives the
// gathers' share (rank 0's clock).
void write_gathered(const Share& s, const std::string& path, int rank, int ranks,
                    double& gather_seconds) {
  const double start = MPI_Wtime();
  const Gathered all = gather_to_rank_0(s, rank, ranks);
  gather_seconds = MPI_Wtime() - start;
  if (rank != 0) return;
  const Handle file = checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                              H5Fclose, "H5Fcreate");
  const auto write = [&](const char* name, hid_t type, int width, const void* data) {
    const Handle d = create_dataset(file.get(), name, type, s.total, width);
    require(H5Dwrite(d.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0, "H5Dwrite");
  };
  write("position", H5T_NATIVE_DOUBLE, 3, all.position.data());
  write("velocity", H5T_NATIVE_DOUBLE, 3, all.velocity.data());
  write("species", H5T_NATIVE_INT, 1, all.species.data());
  write("id", H5T_NATIVE_INT, 1, all.id.data());
}

// Every rank writes its rows through MPI-IO, collectively.
void write_collective(const Share& s, const std::string& path) {
  const Handle access = checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "H5Pcreate");
  require(H5Pset_fapl_mpio(access.get(), MPI_COMM_WORLD, MPI_INFO_NULL) >= 0, "H5Pset_fapl_mpio");
  const Handle file = checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
                              H5Fclose, "H5Fcreate (MPI-IO)");
  const Handle transfer = checked(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "H5Pcreate");
  require(H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE) >= 0, "H5Pset_dxpl_mpio");
  const auto write = [&](const char* name, hid_t type, int width, const void* data) {
    const Handle d = create_dataset(file.get(), name, type, s.total, width);
    const Handle in_file = checked(H5Dget_space(d.get()), H5Sclose, "H5Dget_space");
    const std::array<hsize_t, 2> start{hsize_t(s.first), 0},
        count{hsize_t(s.count), hsize_t(width)};
    require(H5Sselect_hyperslab(in_file.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                                nullptr) >= 0,
            "H5Sselect_hyperslab");
    const Handle in_memory = checked(H5Screate_simple(width == 1 ? 1 : 2, count.data(), nullptr),
                                     H5Sclose, "H5Screate_simple");
    require(H5Dwrite(d.get(), type, in_memory.get(), in_file.get(), transfer.get(), data) >= 0,
            "H5Dwrite (collective)");
  };
  write("position", H5T_NATIVE_DOUBLE, 3, s.position.data());
  write("velocity", H5T_NATIVE_DOUBLE, 3, s.velocity.data());
  write("species", H5T_NATIVE_INT, 1, s.species.data());
  write("id", H5T_NATIVE_INT, 1, s.id.data());
}

// run.h5 as granshock writes it (chunked, compressed, appended frame by frame).
HostParticles particles_of(const std::vector<double>& position, const std::vector<double>& velocity,
                           const std::vector<int>& species, const std::vector<int>& id) {
  HostParticles p;
  for (std::size_t i = 0; i < species.size(); ++i)
    p.add({position[3 * i], position[3 * i + 1], position[3 * i + 2]},
          {velocity[3 * i], velocity[3 * i + 1], velocity[3 * i + 2]}, species[i], id[i]);
  return p;
}

// The gathers of write_gathered, then rank 0 appends the frame to its run file.
void append_gathered(const Share& s, std::optional<RunFile>& file, long step, int rank, int ranks) {
  const Gathered all = gather_to_rank_0(s, rank, ranks);
  if (rank == 0)
    file->append_snapshot(step, double(step),
                          particles_of(all.position, all.velocity, all.species, all.id));
}

// granshock's collective append: each rank writes its rows of the frame.
void append_collective(const Share& s, const std::filesystem::path& path,
                       std::optional<RunFile>& file, long step) {
  SnapshotPart part;
  part.particles = particles_of(s.position, s.velocity, s.species, s.id);
  if (s.count > 0) part.rows.push_back({s.first, s.count});
  part.total = s.total;
  RunFile::append_snapshot_collectively(path, MPI_COMM_WORLD, step, double(step), part, file);
}

template <class Write>
double timed(Write&& write) {
  MPI_Barrier(MPI_COMM_WORLD);
  const double start = MPI_Wtime();
  write();
  MPI_Barrier(MPI_COMM_WORLD);
  return MPI_Wtime() - start;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Plain datasets in a fresh file, gathered against collective: one Markdown table.
void plain_datasets_table(const std::vector<long>& particles, int repeats, const std::string& path,
                          int rank, int ranks) {
  if (rank == 0)
    std::printf(
        "| particles | MB | gathered to rank 0 (s) | of which the gathers (s) | "
        "collective parallel HDF5 (s) | collective / gathered |\n"
        "|---|---|---|---|---|---|\n");
  for (const long total : particles) {
    const Share share = make_share(total, rank, ranks);
    std::vector<double> gathered, gathers, collective;
    for (int r = 0; r < repeats; ++r) {
      double gather_seconds = 0;
      gathered.push_back(timed([&] { write_gathered(share, path, rank, ranks, gather_seconds); }));
      gathers.push_back(gather_seconds);
      if (rank == 0) std::filesystem::remove(path);
      collective.push_back(timed([&] { write_collective(share, path); }));
      MPI_Barrier(MPI_COMM_WORLD);
      if (rank == 0) std::filesystem::remove(path);
    }
    if (rank == 0)
      std::printf("| %ld | %.1f | %.4f | %.4f | %.4f | %.2f |\n", total,
                  double(total) * (6 * sizeof(double) + 2 * sizeof(int)) / 1e6, median(gathered),
                  median(gathers), median(collective), median(collective) / median(gathered));
  }
}

// The same frames appended to run.h5 files, one frame per repeat and way.
void run_file_table(const std::vector<long>& particles, int repeats, const std::string& path,
                    int rank, int ranks) {
  if (rank == 0)
    std::printf(
        "\nrun.h5 (granshock's layout: chunked, shuffle + gzip 1, 2-D), a frame appended per "
        "repeat\n\n| particles | gathered, rank 0 appends (s) | collective append (s) | "
        "collective / gathered |\n|---|---|---|---|\n");
  for (const long total : particles) {
    const Share share = make_share(total, rank, ranks);
    const std::filesystem::path gathered_path = path + ".gathered", collective_path = path;
    std::optional<RunFile> gathered_file, collective_file;
    if (rank == 0) {
      gathered_file.emplace(RunFile::create(gathered_path, "", "", 2));
      collective_file.emplace(RunFile::create(collective_path, "", "", 2));
    }
    std::vector<double> gathered, collective;
    for (int r = 0; r < repeats; ++r) {
      gathered.push_back(timed([&] { append_gathered(share, gathered_file, r + 1, rank, ranks); }));
      collective.push_back(
          timed([&] { append_collective(share, collective_path, collective_file, r + 1); }));
    }
    if (rank == 0) {
      gathered_file.reset();
      collective_file.reset();
      std::filesystem::remove(gathered_path);
      std::filesystem::remove(collective_path);
      std::printf("| %ld | %.4f | %.4f | %.2f |\n", total, median(gathered), median(collective),
                  median(collective) / median(gathered));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::vector<long> particles{31600, 3200000};
  int repeats = 7;
  std::string dir = std::filesystem::temp_directory_path().string();
  CLI::App app{"parallel HDF5 against gathering to rank 0, for one snapshot"};
  app.add_option("--particles", particles, "particle counts")->delimiter(',');
  app.add_option("--repeats", repeats, "writes of each kind per count (interleaved)")
      ->check(CLI::PositiveNumber);
  app.add_option("--dir", dir, "where the files go (removed after each write)")
      ->check(CLI::ExistingDirectory);
  int status = 0;
  try {
    app.parse(argc, argv);
    granshock::h5::silence_error_printing();
    // One name for every rank: rank 0's process id.
    long pid = long(getpid());
    MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
    const std::string path = dir + "/granshock_output_bench_" + std::to_string(pid) + ".h5";
    if (rank == 0)
      std::printf("%d processes, %d repeats each (interleaved), files in %s; medians\n\n", ranks,
                  repeats, dir.c_str());
    plain_datasets_table(particles, repeats, path, rank, ranks);
    run_file_table(particles, repeats, path, rank, ranks);
  } catch (const CLI::ParseError& e) {
    status = rank == 0 ? app.exit(e) : 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "granshock_bench_parallel_output (rank %d): %s\n", rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return status;
}

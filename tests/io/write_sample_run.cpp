// Writes a small run directory (run.h5 + run.xmf in 2-D, run3d.h5 + run3d.xmf in 3-D,
// checkpoint.h5) for the tests that inspect the layout with standard tools (h5dump,
// h5py, an XML parser). With --bench N, times N-particle snapshots instead.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <random>
#include <string>

#include "io/checkpoint_file.hpp"
#include "io/checkpoint_seal.hpp"
#include "io/run_file.hpp"
#include "io/xdmf_writer.hpp"
#include "io_test_support.hpp"

namespace {

using namespace granshock;

void write_run(const std::filesystem::path& dir, const std::string& name, int dim,
               const std::vector<int>& counts, const SnapshotContents& contents) {
  RunFile run = RunFile::create(dir / (name + ".h5"), "# as given\nmach = 5\n",
                                "# resolved\nmach = 5.0\n", dim, contents);
  for (std::size_t f = 0; f < counts.size(); ++f) {
    const long step = 1000 * static_cast<long>(f + 1);
    HostParticles p = test::make_particles(counts[f], static_cast<int>(f));
    if (contents.angular_velocity)
      for (int i = 0; i < counts[f]; ++i) p.angular_velocity.push_back(100.0 * f - i);
    run.append_snapshot(step, 1e-3 * static_cast<double>(f + 1), p);
    TimeSeriesRow row;
    row.step = step;
    row.time = 1e-3 * static_cast<double>(f + 1);
    row.particles = counts[f];
    row.kinetic_energy = 0.5 * counts[f];
    row.temperature = 0.1 * counts[f];
    row.contacts = 2L * counts[f];
    row.inserted = counts[f];
    run.append_time_series(row);
  }
  run.write_attribute("/summary", "mach_measured", 4.9);
  run.write_array("/fields/bin_sums", {1, 2, 3, 4, 5, 6}, {2, 3});
  write_particles_xdmf(dir / (name + ".xmf"), name + ".h5", run.frames(), run.dim(),
                       run.frame_view_arrays());
}

void write_sample_checkpoint(const std::filesystem::path& dir) {
  SolverState s;
  s.dim = 2;
  s.step = 4000;
  s.next_id = 3;
  s.history_slots = 2;
  s.position = {0, 1, 2, 3, 4, 5};
  s.velocity = {0, -1, -2, -3, -4, -5};
  s.force = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
  s.angular_velocity = {1, 2, 3};
  s.torque = {0, 0, 0};
  s.species = {0, 1, 0};
  s.id = {0, 1, 2};
  s.history_partner = {1, -1, 0, -1, -1, -1};
  s.history_spring = {1e-6, 2e-6, 0, 0, -1e-6, -2e-6, 0, 0, 0, 0, 0, 0};  // used slots only
  s.history_obstacle_spring = std::vector<double>(6, 0.0);
  s.reference_position = s.position;
  s.neighbour_offsets = {0, 2, 3, 3};
  s.neighbours = {1, 2, 2};
  s.list_builds = 7;
  s.removed_low = {0, 2, 0};
  s.removed_high = {0, 5, 0};
  CheckpointExtras e;
  e.rng_counter = 42;
  e.inserted = 3;
  e.insertion_carry = 0.25;
  e.wall_seconds_so_far = 1.5;
  e.bin_sums = {1, 2, 3, 4, 5, 6};  // 2 grid, 3 profile sums, samples of 1 block
  e.bin_shape = {2, 3, 1};
  e.scene_resolved = "# resolved\nmach = 5.0\n";
  write_checkpoint(dir / "checkpoint.h5", s, e);
}

int bench(const std::filesystem::path& dir, int n, int dim) {
  // As a run of two species writes them: with each particle's radius and the frame views.
  RunFile run = RunFile::create(dir / "bench.h5", "", "", dim, {{0.5e-3, 0.6e-3}, false});
  const HostParticles p = test::random_particles(n);
  const int frames = 10;
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) run.append_snapshot(f + 1, 0.1 * f, p);
  run.flush();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d particles, dim %d: %.1f ms per snapshot, %.2f MB per snapshot on disk\n", n, dim,
              1e3 * seconds / frames,
              static_cast<double>(std::filesystem::file_size(dir / "bench.h5")) / 1e6 / frames);
  return 0;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The cost of the checkpoint checksum: a frictional 2-D state of n particles with 4
// neighbours each and 0.5 M bin sums (the default scene's size), written and read a few
// times. The seal (hash pass + header) is timed again alone on the written file, which
// is in the page cache as it is right after HDF5 closes it: that is what it adds.
int bench_checkpoint(const std::filesystem::path& dir, int n) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  SolverState s;
  s.next_id = n;
  s.history_slots = 8;
  const auto un = static_cast<std::size_t>(n);
  auto fill = [&](std::vector<double>& v, std::size_t count) {
    v.resize(count);
    for (double& x : v) x = value(rng);
  };
  for (auto* v :
       {&s.position, &s.velocity, &s.force, &s.reference_position, &s.history_obstacle_spring})
    fill(*v, 2 * un);
  fill(s.angular_velocity, un);
  fill(s.torque, un);
  fill(s.history_spring, 16 * un);
  // Two contacts per particle (its next two), six free slots with zero springs.
  s.history_partner.assign(8 * un, -1);
  for (std::size_t i = 0; i < un; ++i) {
    for (std::size_t a = 0; a < 8; ++a) {
      if (a < 2) {
        s.history_partner[8 * i + a] = static_cast<int>((i + a + 1) % un);
      } else {
        s.history_spring[16 * i + 2 * a] = s.history_spring[16 * i + 2 * a + 1] = 0;
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    s.species.push_back(i % 2);
    s.id.push_back(i);
    s.neighbour_offsets.push_back(4 * i);
    for (int k = 1; k <= 4; ++k) s.neighbours.push_back((i + k) % n);
  }
  s.neighbour_offsets.push_back(4 * n);
  CheckpointExtras e;
  fill(e.bin_sums, 528000);
  e.bin_shape = {528000, 0, 0};
  const auto path = dir / "checkpoint.h5";
  const int repeats = 5;
  double write = 0, hash = 0, read = 0;
  for (int r = 0; r < repeats; ++r) {
    auto start = std::chrono::steady_clock::now();
    write_checkpoint(path, s, e);
    write += seconds_since(start);
    start = std::chrono::steady_clock::now();
    seal::seal_file(path, kCheckpointFormat);  // as write_checkpoint seals it
    hash += seconds_since(start);
    CheckpointExtras back;
    start = std::chrono::steady_clock::now();
    static_cast<void>(read_checkpoint(path, back));
    read += seconds_since(start);
  }
  const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::printf(
      "checkpoint of %d particles, %.1f MB: write %.1f ms, of which the seal %.1f ms (%.1f %%; "
      "%.2f GB/s); read %.1f ms\n",
      n, mb, 1e3 * write / repeats, 1e3 * hash / repeats, 100 * hash / write,
      mb / 1e3 / (hash / repeats), 1e3 * read / repeats);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 5 && std::string(argv[1]) == "--bench") {
      return bench(argv[2], std::atoi(argv[3]), std::atoi(argv[4]));
    }
    if (argc == 4 && std::string(argv[1]) == "--bench-checkpoint") {
      return bench_checkpoint(argv[2], std::atoi(argv[3]));
    }
    // An option-like DIR is a mistyped flag, not a directory to create (a stray
    // `write_sample_run --help` once wrote its files into ./--help).
    if (argc != 2 || argv[1][0] == '-') {
      std::fprintf(stderr, "usage: %s DIR | --bench DIR N DIM | --bench-checkpoint DIR N\n",
                   argv[0]);
      return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    // 2-D with friction (radius and angular velocity), 3-D without (radius alone); the
    // species of make_particles are 0, 1, 2.
    write_run(dir, "run", 2, {5, 12, 0, 3}, {{0.5e-3, 0.6e-3, 0.75e-3}, true});
    write_run(dir, "run3d", 3, {4, 2}, {{1e-3, 1e-3, 2e-3}, false});
    write_sample_checkpoint(dir);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

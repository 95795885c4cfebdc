// The memory a run needs, estimated before it starts (cases/bow_shock/run_memory.hpp):
// against the bytes Kokkos allocates in a run, and the refusal of scenes past the
// available memory, naming the key that drives the estimate (numerics.skin = 300 d once
// allocated for 9 minutes and died at "167.1 G").
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cstdio>
#include <map>
#include <string>

#include "cases/bow_shock/run_command.hpp"
#include "cases/bow_shock/run_memory.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "kernels/device/backends.hpp"
#include "run_helpers.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using namespace granshock::testing;

namespace {

// Kokkos' live and peak bytes while the callbacks are installed.
std::map<const void*, std::uint64_t> g_live;
std::uint64_t g_bytes = 0, g_peak = 0;
void on_allocate(Kokkos::Tools::SpaceHandle, const char*, const void* ptr, std::uint64_t n) {
  g_live[ptr] = n;
  g_bytes += n;
  g_peak = std::max(g_peak, g_bytes);
}
void on_deallocate(Kokkos::Tools::SpaceHandle, const char*, const void* ptr, std::uint64_t n) {
  if (g_live.erase(ptr) != 0) g_bytes -= n;
}

// small_scene() grown to a channel of about 10,000 particles at phi = 0.3 with a skin of
// 3 d, so that particles and lists weigh as much as the field sums.
std::vector<std::string> grown() {
  return {"domain.width=\"120 d\"",
          "domain.length=\"240 d\"",
          "obstacle.diameter=\"30 d\"",
          "obstacle.centre=[\"60 d\", \"150 d\"]",
          "inflow.area_fraction=0.3",
          "numerics.skin=\"3 d\"",
          "numerics.bin_size=\"8 d\"",
          "output.blocks=4",
          "time.duration=0.004",
          "time.production_start=0.002",
          "output.sample_every=10",
          "output.snapshot_interval=0.002",
          "output.checkpoint_interval=0.002",
          "output.series_interval=0.0005"};
}

std::string refusal(const Scene& s, double available) {
  try {
    check_run_memory(s, estimate_run_memory(s), available);
  } catch (const UserError& e) {
    return e.what();
  }
  return "(fits)";
}

}  // namespace

// The solver's arrays as Kokkos allocates them, at their peak over the prefill, list
// builds, sampling, a snapshot and a checkpoint: the estimate (device part) within 25 %.
TEST(RunMemory, TheEstimateMatchesWhatKokkosAllocates) {
  TempDir tmp;
  const auto scene_file = tmp.write("s.toml", small_scene(true));
  RunOptions o = run_options(scene_file, tmp.path() / "out", grown());
  o.stop_after_steps = 20;
  const Scene scene = load_scene_file(scene_file, o.overrides).scene;
  const MemoryEstimate m = estimate_run_memory(scene);
  g_live.clear();
  g_bytes = g_peak = 0;
  Kokkos::Tools::Experimental::set_allocate_data_callback(on_allocate);
  Kokkos::Tools::Experimental::set_deallocate_data_callback(on_deallocate);
  const int code = run_scene(o);
  Kokkos::Tools::Experimental::set_allocate_data_callback(nullptr);
  Kokkos::Tools::Experimental::set_deallocate_data_callback(nullptr);
  ASSERT_EQ(code, 0);
  std::printf(
      "[ measured ] Kokkos peak %.2f MB; estimate %.2f MB (particles %.2f, lists %.2f, cells "
      "%.3f, field sums %.2f) and %.2f MB of host copies\n",
      g_peak / 1e6, m.device() / 1e6, m.particles / 1e6, m.lists / 1e6, m.cells / 1e6,
      m.field_sums / 1e6, m.host / 1e6);
  EXPECT_GT(m.lists, 0.2 * m.device()) << "the lists must weigh in this scene";
  EXPECT_NEAR(m.device() / double(g_peak), 1.0, 0.25);
}

// What drives the estimate is named, with the parts; a scene that fits passes.
TEST(RunMemory, ScenesPastTheAvailableMemoryAreRefusedNamingTheKey) {
  const Scene fits = parse_scene(small_scene(true)).scene;
  EXPECT_EQ(refusal(fits, 1e9), "(fits)");
  // numerics.skin = 300 d on a 1000 d domain: lists of some 70,000 partners per particle.
  const Scene skin =
      parse_scene(small_scene(true),
                  {"numerics.skin=\"300 d\"", "domain.width=\"1000 d\"", "domain.length=\"1000 d\"",
                   "obstacle.centre=[\"500 d\", \"500 d\"]"})
          .scene;
  EXPECT_EQ(refusal(skin, 1e9).rfind("scene key 'numerics.skin' = 0.3 m (300 particle diameters): "
                                     "the run needs about ",
                                     0),
            0u)
      << refusal(skin, 1e9);
  // Host paths build the list in per-thread parts as well, twice its size (docs/cuda.md,
  // "Branch points"); a GPU, or the device paths on the host, do not.
  const double list_bytes = uses_host_paths<Kokkos::DefaultExecutionSpace>() ? 5e10 : 2.5e10;
  EXPECT_GT(estimate_run_memory(skin).lists, list_bytes);
  // Particles: 3,000 d square at phi = 0.3.
  const Scene many =
      parse_scene(small_scene(true), {"domain.width=\"3000 d\"", "domain.length=\"3000 d\"",
                                      "inflow.area_fraction=0.3", "numerics.bin_size=\"9 d\""})
          .scene;
  EXPECT_NE(refusal(many, 1e9).find("scene keys 'domain.width' x 'domain.length' at "
                                    "'inflow.area_fraction' = 0.3 (about 5.16e+06 particles)"),
            std::string::npos)
      << refusal(many, 1e9);
  EXPECT_NE(refusal(many, 1e9).find("more than the 1 GB available"), std::string::npos);
  // Field sums: many blocks of small bins.
  const Scene sums = parse_scene(small_scene(true), {"output.blocks=2000", "output.sample_every=1",
                                                     "numerics.bin_size=\"1 d\""})
                         .scene;
  EXPECT_NE(refusal(sums, 1e8).find("scene keys 'numerics.bin_size' = 0.001 m x 'output.blocks' "
                                    "= 2000"),
            std::string::npos)
      << refusal(sums, 1e8);
}

// Several processes share the particles, lists and cells; each holds all the field sums.
TEST(RunMemory, ProcessesShareTheParticlesNotTheFieldSums) {
  const Scene s = parse_scene(small_scene(true), grown()).scene;
  const MemoryEstimate one = estimate_run_memory(s, 1, 2), four = estimate_run_memory(s, 4, 2);
  EXPECT_NEAR(four.particles, one.particles / 4, 1e-6 * one.particles);
  EXPECT_NEAR(four.lists, one.lists / 4, 1e-6 * one.lists);
  EXPECT_EQ(four.field_sums, one.field_sums);
}

TEST(RunMemory, AvailableMemoryIsRead) {
  const auto available = available_memory_bytes();
  ASSERT_TRUE(available.has_value()) << "/proc/meminfo has no MemAvailable";
  EXPECT_GT(*available, 1e6);
}

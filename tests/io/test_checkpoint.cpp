// checkpoint.h5: exact round trips (bitwise for doubles, exact for float-derived
// values), atomic replacement, and clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>

#include "core/user_error.hpp"
#include "io/checkpoint_edit.hpp"
#include "io/checkpoint_file.hpp"
#include "io/io_test_support.hpp"
#include "io/run_file.hpp"

namespace granshock {
namespace {

using test::TempDir;

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

void expect_equal(const SolverState& a, const SolverState& b) {
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.next_id, b.next_id);
  EXPECT_EQ(a.history_slots, b.history_slots);
  EXPECT_TRUE(same_bits(a.position, b.position));
  EXPECT_TRUE(same_bits(a.velocity, b.velocity));
  EXPECT_TRUE(same_bits(a.force, b.force));
  EXPECT_TRUE(same_bits(a.angular_velocity, b.angular_velocity));
  EXPECT_TRUE(same_bits(a.torque, b.torque));
  EXPECT_EQ(a.species, b.species);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.history_partner, b.history_partner);
  EXPECT_TRUE(same_bits(a.history_spring, b.history_spring));
  EXPECT_TRUE(same_bits(a.history_obstacle_spring, b.history_obstacle_spring));
  EXPECT_TRUE(same_bits(a.contact_virial, b.contact_virial));
  EXPECT_TRUE(same_bits(a.reference_position, b.reference_position));
  EXPECT_EQ(a.neighbour_offsets, b.neighbour_offsets);
  EXPECT_EQ(a.neighbours, b.neighbours);
  EXPECT_EQ(a.list_builds, b.list_builds);
  EXPECT_EQ(a.skin, b.skin);
  EXPECT_EQ(a.last_build_step, b.last_build_step);
  EXPECT_EQ(a.removed_low, b.removed_low);
  EXPECT_EQ(a.removed_high, b.removed_high);
}

// A state with awkward doubles: no short decimal form, signed zero, subnormal, extremes.
template <class Real>
SolverState make_state(int n, int dim, int slots, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto value = [&]() { return static_cast<double>(static_cast<Real>(uniform(rng) / 3.0)); };
  SolverState s;
  s.dim = dim;
  s.step = 1234567890123L;
  s.next_id = 3 * n + 17;  // above every id 3 i + 1
  s.history_slots = slots;
  const std::size_t un = static_cast<std::size_t>(n);
  const std::size_t ud = static_cast<std::size_t>(dim);
  const std::size_t us = static_cast<std::size_t>(slots);
  for (std::size_t i = 0; i < un * ud; ++i) {
    s.position.push_back(value());
    s.velocity.push_back(value());
    s.force.push_back(value());
  }
  if (un * ud >= 4) {
    s.position[0] = -0.0;
    s.position[1] = static_cast<double>(std::numeric_limits<Real>::denorm_min());
    s.position[2] = static_cast<double>(std::numeric_limits<Real>::max());
    s.position[3] = static_cast<double>(std::numeric_limits<Real>::lowest());
  }
  for (int i = 0; i < n; ++i) {
    s.species.push_back(i % 2);
    s.id.push_back(3 * i + 1);
  }
  // A neighbour list: particle i lists its next (i % 3) particles.
  s.neighbour_offsets.push_back(0);
  for (int i = 0; i < n; ++i) {
    for (int k = 1; k <= i % 3; ++k) s.neighbours.push_back((i + k) % n);
    s.neighbour_offsets.push_back(static_cast<int>(s.neighbours.size()));
  }
  for (std::size_t i = 0; i < un * ud; ++i) s.reference_position.push_back(value());
  s.list_builds = 4321;
  s.skin = 1.0 / 7.0 * 1e-4;  // an adaptive skin: no short decimal form
  s.last_build_step = s.step - 321;
  s.removed_low = {1, 20000000000L, 3};
  s.removed_high = {4, 5, 6};
  if (slots > 0) {
    // About z in 2-D, a vector in 3-D (core/solver_state.hpp).
    for (std::size_t i = 0; i < un * std::size_t(spin_components(dim)); ++i) {
      s.angular_velocity.push_back(value());
      s.torque.push_back(value());
    }
    // Slot a of particle p holds particle (p + a) % n, or is free (a % 3 == 0) with a
    // zero spring, as the force kernel leaves free slots.
    for (std::size_t i = 0; i < un * us; ++i) {
      const std::size_t p = i / us, a = i % us;
      const bool free = a % 3 == 0;
      s.history_partner.push_back(free ? -1 : s.id[(p + a) % un]);
      for (std::size_t d = 0; d < ud; ++d) s.history_spring.push_back(free ? 0.0 : value());
    }
    for (std::size_t i = 0; i < un * ud; ++i) s.history_obstacle_spring.push_back(value());
  }
  for (std::size_t i = 0; i < un * ud * ud; ++i) s.contact_virial.push_back(value());
  return s;
}

CheckpointExtras make_extras() {
  CheckpointExtras e;
  e.rng_counter = (std::uint64_t{1} << 63) + 5;  // needs all 64 unsigned bits
  e.inserted = 100000;
  e.deleted_outlet = 2500;
  e.deleted_inlet = 3;
  e.insertion_carry = 0.1 + 0.2;
  e.wall_seconds_so_far = 3600.125;
  e.cpu_seconds_so_far = 7000.25;
  e.bin_sums = {1.0 / 3.0, 2.0, -0.0, 4e-300, 5, 6};  // 2 grid, 3 profile sums, 1 block
  e.bin_shape = {2, 3, 1};
  e.scene_resolved = "[domain]\nwidth = 0.5\n# ünïcode survives\n";
  return e;
}

TEST(Checkpoint, DoubleStateWithoutFrictionRoundTripsBitwise) {
  TempDir dir;
  const SolverState state = make_state<double>(50, 2, 0, 1);
  write_checkpoint(dir / "checkpoint.h5", state, make_extras());
  CheckpointExtras extras;
  const SolverState back = read_checkpoint(dir / "checkpoint.h5", extras);
  expect_equal(state, back);
  EXPECT_TRUE(back.angular_velocity.empty());
  EXPECT_TRUE(back.history_partner.empty());
}

TEST(Checkpoint, FloatDerivedStateWithFrictionHistoryRoundTripsExactly) {
  TempDir dir;
  const SolverState state = make_state<float>(40, 3, 4, 2);
  write_checkpoint(dir / "checkpoint.h5", state, make_extras());
  CheckpointExtras extras;
  const SolverState back = read_checkpoint(dir / "checkpoint.h5", extras);
  expect_equal(state, back);
  // A float solver gets its own values back after double -> float.
  for (std::size_t i = 0; i < state.history_spring.size(); ++i) {
    EXPECT_EQ(static_cast<float>(back.history_spring[i]),
              static_cast<float>(state.history_spring[i]));
  }
  EXPECT_EQ(back.history_partner.size(), 40u * 4u);
}

TEST(Checkpoint, FloatDerivedStateWithoutFrictionRoundTripsExactly) {
  TempDir dir;
  const SolverState state = make_state<float>(33, 2, 0, 3);
  write_checkpoint(dir / "checkpoint.h5", state, make_extras());
  CheckpointExtras extras;
  expect_equal(state, read_checkpoint(dir / "checkpoint.h5", extras));
}

TEST(Checkpoint, EmptyStateAndOptionalArraysRoundTrip) {
  TempDir dir;
  SolverState state;  // no particles at all (a run before the first insertion)
  state.step = 7;
  CheckpointExtras none;
  write_checkpoint(dir / "checkpoint.h5", state, none);
  CheckpointExtras extras = make_extras();
  expect_equal(state, read_checkpoint(dir / "checkpoint.h5", extras));
  EXPECT_TRUE(extras.bin_sums.empty());
  EXPECT_TRUE(extras.bin_shape.empty());
  EXPECT_EQ(extras.scene_resolved, "");
  EXPECT_EQ(extras.rng_counter, 0u);

  // Friction on (slots > 0) but no wall springs yet: the empty array stays empty.
  SolverState partial = make_state<double>(5, 2, 2, 4);
  partial.history_obstacle_spring.clear();
  write_checkpoint(dir / "checkpoint.h5", partial, none);
  expect_equal(partial, read_checkpoint(dir / "checkpoint.h5", extras));

  // No contact virial (a solver that held none, as in files from before it): none read.
  partial.contact_virial.clear();
  write_checkpoint(dir / "checkpoint.h5", partial, none);
  expect_equal(partial, read_checkpoint(dir / "checkpoint.h5", extras));
}

TEST(Checkpoint, ExtrasRoundTrip) {
  TempDir dir;
  const CheckpointExtras e = make_extras();
  write_checkpoint(dir / "checkpoint.h5", make_state<double>(3, 2, 0, 5), e);
  CheckpointExtras back;
  read_checkpoint(dir / "checkpoint.h5", back);
  EXPECT_EQ(back.rng_counter, e.rng_counter);
  EXPECT_EQ(back.inserted, e.inserted);
  EXPECT_EQ(back.deleted_outlet, e.deleted_outlet);
  EXPECT_EQ(back.deleted_inlet, e.deleted_inlet);
  EXPECT_EQ(back.insertion_carry, e.insertion_carry);
  EXPECT_EQ(back.wall_seconds_so_far, e.wall_seconds_so_far);
  EXPECT_EQ(back.cpu_seconds_so_far, e.cpu_seconds_so_far);
  EXPECT_TRUE(same_bits(back.bin_sums, e.bin_sums));
  EXPECT_EQ(back.bin_shape, e.bin_shape);
  EXPECT_EQ(back.scene_resolved, e.scene_resolved);
}

TEST(Checkpoint, ReplacesAtomicallyAndLeavesNoTmp) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, make_state<double>(10, 2, 0, 6), make_extras());
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  const SolverState newer = make_state<double>(12, 2, 0, 7);
  write_checkpoint(path, newer, make_extras());
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  CheckpointExtras extras;
  expect_equal(newer, read_checkpoint(path, extras));
}

TEST(Checkpoint, UnwritableDirectoryIsAUserErrorAndLeavesNothing) {
  TempDir dir;
  // Root may write anywhere, but nobody can create a file below a regular file or in
  // a directory that does not exist.
  std::ofstream(dir / "plain_file") << "x";
  for (const auto& path :
       {dir / "plain_file" / "checkpoint.h5", dir / "missing" / "checkpoint.h5"}) {
    try {
      write_checkpoint(path, make_state<double>(2, 2, 0, 8), make_extras());
      FAIL() << "no exception for " << path;
    } catch (const UserError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

TEST(Checkpoint, InconsistentArraysAreRejectedBeforeTouchingTheTarget) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  const SolverState good = make_state<double>(4, 2, 0, 9);
  write_checkpoint(path, good, make_extras());
  SolverState bad = good;
  bad.position.pop_back();  // 7 values for dim 2
  EXPECT_THROW(write_checkpoint(path, bad, make_extras()), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
  bad = good;
  bad.history_partner = {1, 2};  // values but zero slots
  EXPECT_THROW(write_checkpoint(path, bad, make_extras()), std::invalid_argument);
  CheckpointExtras extras;
  expect_equal(good, read_checkpoint(path, extras));  // the old checkpoint is intact
}

TEST(Checkpoint, ReadingWhatIsNotACheckpointIsAUserError) {
  TempDir dir;
  CheckpointExtras extras;
  EXPECT_THROW(read_checkpoint(dir / "missing.h5", extras), UserError);
  std::ofstream(dir / "text.h5") << "not hdf5";
  EXPECT_THROW(read_checkpoint(dir / "text.h5", extras), UserError);
  { RunFile::create(dir / "run.h5", "", "", 2); }
  try {
    read_checkpoint(dir / "run.h5", extras);
    FAIL() << "no exception";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("not a granshock checkpoint"), std::string::npos)
        << e.what();
  }
}

// Format-3 checkpoints written before the adaptive skin and the CPU-time record lack
// @skin, @last_build_step and @cpu_seconds_so_far: they read as the scene's skin (0), the
// last build at the stored step and an unknown CPU time (io/checkpoint_file.hpp). Format 4
// always holds them: a format-4 file without one is refused, naming it.
void delete_format_four_records(hid_t f) {
  const hid_t state = H5Gopen2(f, "/state", H5P_DEFAULT);
  test::h5_ok(H5Adelete(state, "skin"), "deleting @skin");
  test::h5_ok(H5Adelete(state, "last_build_step"), "deleting @last_build_step");
  H5Gclose(state);
  const hid_t run = H5Gopen2(f, "/run", H5P_DEFAULT);
  test::h5_ok(H5Adelete(run, "cpu_seconds_so_far"), "deleting @cpu_seconds_so_far");
  H5Gclose(run);
}

TEST(Checkpoint, FormatThreeWithoutSkinOrCpuTimeReadsAsTheScenesSkin) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  const SolverState state = make_state<double>(8, 2, 0, 4);
  write_checkpoint(path, state, make_extras());
  test::rewrite_as_format(path, 3, delete_format_four_records);
  CheckpointExtras extras;
  const SolverState back = read_checkpoint(path, extras);
  EXPECT_EQ(back.skin, 0.0);
  EXPECT_EQ(back.last_build_step, state.step);
  EXPECT_EQ(extras.cpu_seconds_so_far, -1.0);
  EXPECT_TRUE(same_bits(back.position, state.position));
}

TEST(Checkpoint, FormatFourWithoutSkinIsRefused) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, make_state<double>(8, 2, 0, 4), make_extras());
  test::edit_checkpoint(path, delete_format_four_records);
  CheckpointExtras extras;
  try {
    read_checkpoint(path, extras);
    FAIL() << "a format-4 checkpoint without /state@skin was read";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("/state@skin"), std::string::npos) << e.what();
  }
}

// A format-3 checkpoint whose contents are format 4's reads the same (every file this
// granshock wrote before format 4 did is such a file), and a root that disagrees with
// its header is refused.
TEST(Checkpoint, FormatThreeReadsAsFormatFour) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  const SolverState state = make_state<double>(8, 2, 0, 4);
  write_checkpoint(path, state, make_extras());
  test::rewrite_as_format(path, 3);
  CheckpointExtras extras;
  const SolverState back = read_checkpoint(path, extras);
  EXPECT_EQ(back.skin, state.skin);
  EXPECT_EQ(back.last_build_step, state.last_build_step);
  EXPECT_EQ(extras.cpu_seconds_so_far, make_extras().cpu_seconds_so_far);
  test::edit_checkpoint(
      path, [](hid_t f) { test::set_format_version(f, 4); }, 3);
  try {
    read_checkpoint(path, extras);
    FAIL() << "a root format that disagrees with the header was read";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("disagrees with its header's 3"), std::string::npos)
        << e.what();
  }
}

TEST(Checkpoint, StoresNaturalShapes) {
  TempDir dir;
  const auto path = dir / "checkpoint.h5";
  write_checkpoint(path, make_state<double>(6, 2, 3, 10), make_extras());
  using test::read_array;
  EXPECT_EQ(read_array<double>(path, "/state/position").shape, (std::vector<hsize_t>{6, 2}));
  EXPECT_EQ(read_array<double>(path, "/state/angular_velocity").shape, (std::vector<hsize_t>{6}));
  EXPECT_EQ(read_array<int>(path, "/state/history_partner").shape, (std::vector<hsize_t>{6, 3}));
  EXPECT_EQ(read_array<double>(path, "/state/history_spring").shape,
            (std::vector<hsize_t>{6, 3, 2}));
  EXPECT_EQ(read_array<long>(path, "/run/bin_shape").values, (std::vector<long>{2, 3, 1}));
  EXPECT_EQ(read_array<double>(path, "/state/reference_position").shape,
            (std::vector<hsize_t>{6, 2}));
  EXPECT_EQ(read_array<int>(path, "/state/neighbour_offsets").shape, (std::vector<hsize_t>{7}));
}

}  // namespace
}  // namespace granshock

// The reported defects: a checkpoint damaged in ways its checksum cannot see (edited,
// then re-sealed) crashed `granshock run --resume` (neighbour index 0x7fffffff, species
// -1000000: segmentation fault) or was silently accepted (NaN positions, random bin
// sums). Each must end in one clear line naming the file and the dataset.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

#include "core/user_error.hpp"
#include "io/checkpoint_edit.hpp"
#include "scene_fixtures.hpp"
#include "stopped_run.hpp"

using namespace granshock;
using granshock::testing::small_scene;
using granshock::testing::StoppedRun;
namespace fs = std::filesystem;

namespace {

class DamagedCheckpoint : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // 0.2 ms (1000 steps), fields sampled every 5 steps from step 500; stopped at 700.
    // A set-up that throws would only skip the tests: keep the message to fail them.
    try {
      run_ = new StoppedRun(
          small_scene(true),
          {"time.duration=0.0002", "time.production_start=0.0001", "output.sample_every=5"}, 700,
          10);
    } catch (const std::exception& e) {
      setup_error_ = e.what();
    }
  }
  void SetUp() override { ASSERT_NE(run_, nullptr) << "the stopped run failed: " << setup_error_; }
  static void TearDownTestSuite() {
    delete run_;
    run_ = nullptr;
  }

  // Resumes a copy of the stopped run after `edit`; the UserError's message, or "" when
  // the resume was accepted.
  static std::string resume_after(const std::function<void(hid_t)>& edit) {
    const fs::path dir = run_->copy("damaged");
    test::edit_checkpoint(dir / "checkpoint.h5", edit);
    try {
      run_->resume(dir);
    } catch (const UserError& e) {
      return e.what();
    }
    return "";
  }

  static void expect_refusal(const std::string& message, const std::string& dataset) {
    std::printf("[ refused  ] %s\n", message.c_str());
    EXPECT_NE(message.find("checkpoint.h5"), std::string::npos) << message;
    EXPECT_NE(message.find(dataset), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }

  static StoppedRun* run_;
  static std::string setup_error_;
};

StoppedRun* DamagedCheckpoint::run_ = nullptr;
std::string DamagedCheckpoint::setup_error_;

TEST_F(DamagedCheckpoint, UnchangedResumesLikeTheUninterruptedRun) {
  EXPECT_EQ(resume_after([](hid_t) {}), "");
  EXPECT_TRUE(granshock::testing::same_run(
      run_->reference_checkpoint(), run_->base().parent_path() / "damaged" / "checkpoint.h5"));
}

TEST_F(DamagedCheckpoint, NeighbourIndexPastTheParticlesIsRefused) {
  expect_refusal(
      resume_after([](hid_t f) { test::set_int(f, "/state/neighbours", 3, 0x7fffffff); }),
      "/state/neighbours");
}

TEST_F(DamagedCheckpoint, SpeciesOutOfRangeIsRefused) {
  expect_refusal(resume_after([](hid_t f) { test::set_int(f, "/state/species", 5, -1000000); }),
                 "/state/species");
}

TEST_F(DamagedCheckpoint, NaNPositionIsRefused) {
  expect_refusal(resume_after([](hid_t f) {
                   test::set_double(f, "/state/position", 7,
                                    std::numeric_limits<double>::quiet_NaN());
                 }),
                 "/state/position");
}

TEST_F(DamagedCheckpoint, RandomBinSumsAreRefused) {
  expect_refusal(resume_after([](hid_t f) {
                   test::RawDataset sums;
                   test::read_raw(f, "/run/bin_sums", sums);
                   std::mt19937_64 rng(11);
                   std::vector<double> random(sums.elements());
                   for (double& v : random) {
                     const std::uint64_t bits = rng();
                     std::memcpy(&v, &bits, sizeof v);
                   }
                   test::set_doubles(f, "/run/bin_sums", random);
                 }),
                 "/run/bin_sums");
}

// The checks refuse nothing a real run writes: checkpoints of other compiled variants
// (the suite above uses double precision, no friction, an obstacle; the fuzzer double
// precision with friction and obstacle) pass them and resume bitwise.
struct Variant {
  const char* name;
  bool obstacle;
  std::vector<std::string> sets;
};

class ValidCheckpoint : public ::testing::TestWithParam<Variant> {};

TEST_P(ValidCheckpoint, PassesEveryCheckAndResumesBitwise) {
  std::vector<std::string> sets = {"time.duration=0.0002", "time.production_start=0.0001",
                                   "output.sample_every=5"};
  sets.insert(sets.end(), GetParam().sets.begin(), GetParam().sets.end());
  const StoppedRun run(small_scene(GetParam().obstacle), sets, 700, 10);
  const fs::path dir = run.copy("resumed");
  ASSERT_EQ(run.resume(dir), 0);
  EXPECT_TRUE(granshock::testing::same_run(run.reference_checkpoint(), dir / "checkpoint.h5"));
}

INSTANTIATE_TEST_SUITE_P(
    Variants, ValidCheckpoint,
    ::testing::Values(Variant{"single_friction_obstacle",
                              true,
                              {"numerics.precision=single", "contact.friction=0.5"}},
                      Variant{"double_friction_no_obstacle", false, {"contact.friction=0.5"}},
                      Variant{
                          "single_no_friction_no_obstacle", false, {"numerics.precision=single"}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

// Damage that only the solver's own arithmetic shows (DemSolver::check_lists).
TEST_F(DamagedCheckpoint, PositionFarFromItsReferenceIsRefused) {
  expect_refusal(resume_after([](hid_t f) {
                   test::RawDataset x;
                   test::read_raw(f, "/state/position", x);
                   double value;
                   std::memcpy(&value, x.bytes.data() + 8, sizeof value);
                   test::set_double(f, "/state/position", 1, value + 2e-4);  // skin/2 = 1.5e-4
                 }),
                 "more than half the skin");
}

TEST_F(DamagedCheckpoint, ReferencePositionOutsideTheBoxIsRefused) {
  expect_refusal(
      resume_after([](hid_t f) { test::set_double(f, "/state/reference_position", 2, -1e-3); }),
      "/state/reference_position[2]");
}

TEST_F(DamagedCheckpoint, NeighbourListThePositionsDoNotGiveIsRefused) {
  expect_refusal(resume_after([](hid_t f) {
                   test::RawDataset list;
                   test::read_raw(f, "/state/neighbours", list);
                   int first;
                   std::memcpy(&first, list.bytes.data(), sizeof first);
                   test::set_int(f, "/state/neighbours", 0, first == 0 ? 1 : 0);
                 }),
                 "/state/neighbours[0]");
}

}  // namespace

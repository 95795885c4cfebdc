// The checkpoint fuzzer: many mutations of a real checkpoint (a small frictional run
// with many contacts, past the start of its field sampling), each followed by
// `granshock run --resume`.
// Every mutation must end in a clean refusal (UserError) or in a resumed run whose next
// checkpoint is bitwise the uninterrupted run's (a mutation that changed nothing, such
// as deleting @creator_version). A crash, a hang (ctest's timeout) or any other
// exception fails. Fixed seed; the loop stops after kMutations or, once kMinimum are
// done, after kSeconds. For a deeper search set GRANSHOCK_FUZZ_SEED,
// GRANSHOCK_FUZZ_MUTATIONS and GRANSHOCK_FUZZ_SECONDS.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "checkpoint_mutations.hpp"
#include "core/user_error.hpp"
#include "scene_fixtures.hpp"
#include "stopped_run.hpp"

using namespace granshock;
using namespace granshock::testing;
namespace fs = std::filesystem;

namespace {

// About 3000 mutations take 4 s on the idle 2-core development machine; under load the
// time limit stops the loop earlier, but never before kMinimum mutations.
constexpr int kMutations = 3000;
constexpr double kSeconds = 12;
constexpr int kMinimum = 200;

double from_environment(const char* name, double fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::atof(value) : fallback;
}

enum class Kind {
  raw_bytes,
  element,
  attribute,
  truncate,
  extend,
  delete_dataset,
  delete_attribute,
  swap
};
const char* name(Kind k) {
  const char* names[] = {"raw bytes",        "dataset element", "attribute",
                         "truncate dataset", "extend dataset",  "delete dataset",
                         "delete attribute", "swap datasets"};
  return names[int(k)];
}

// Applies one mutation of `kind` to the checkpoint at `path` (pristine bytes given).
std::string mutate(Kind kind, const fs::path& path, const std::string& pristine, Rng& rng) {
  if (kind == Kind::raw_bytes) {
    std::string bytes = pristine;
    const std::string what = mutate_bytes(bytes, rng);
    test::write_bytes(path, bytes);
    return what;
  }
  test::write_bytes(path, pristine);
  std::string what;
  test::edit_checkpoint(path, [&](hid_t file) {
    const Objects objects = list_objects(file);
    const auto& sets = objects.datasets;
    const auto& attrs = objects.attributes;
    const std::string& set = sets[pick(rng, sets.size())];
    const auto& attr = attrs[pick(rng, attrs.size())];
    switch (kind) {
      case Kind::element:
        what = set_dataset_element(file, set, rng);
        break;
      case Kind::attribute:
        what = set_attribute_element(file, attr.first, attr.second, rng);
        break;
      case Kind::truncate:
        what = resize_dataset(file, set, false);
        break;
      case Kind::extend:
        what = resize_dataset(file, set, true);
        break;
      case Kind::delete_dataset:
        test::h5_ok(H5Ldelete(file, set.c_str(), H5P_DEFAULT), "deleting");
        what = "delete " + set;
        break;
      case Kind::delete_attribute:
        test::h5_ok(H5Adelete_by_name(file, attr.first.c_str(), attr.second.c_str(), H5P_DEFAULT),
                    "deleting");
        what = "delete " + attr.first + "@" + attr.second;
        break;
      default: {
        const std::string& other = sets[pick(rng, sets.size())];
        what = other == set ? "swap " + set + " with itself" : swap_datasets(file, set, other);
      }
    }
  });
  return what;
}

// "refused: damaged" (checksum), "refused: invalid" (semantic checks), "refused: other"
// (unreadable structure, a changed scene, ...), or "accepted: identical". The resume
// reads the checkpoint before anything that depends on it, so a checkpoint that
// read_checkpoint refuses is refused by the resume alike: tried first, it saves the
// scene and solver set-up of a whole resume.
std::string outcome(const StoppedRun& run, const fs::path& dir, std::string& failure) {
  try {
    CheckpointExtras extras;
    static_cast<void>(read_checkpoint(dir / "checkpoint.h5", extras));
    run.resume(dir);
  } catch (const UserError& e) {
    const std::string message = e.what();
    if (message.find('\n') != std::string::npos) failure = "a message of several lines: " + message;
    if (message.find("is damaged") != std::string::npos) return "refused: damaged";
    if (message.find("is invalid") != std::string::npos) return "refused: invalid";
    return "refused: other";
  } catch (const std::exception& e) {
    failure = std::string("not a UserError: ") + e.what();
    return "failed";
  }
  if (!same_run(run.reference_checkpoint(), dir / "checkpoint.h5")) {
    failure = "accepted, and the resumed run differs from the uninterrupted one";
    return "failed";
  }
  return "accepted: identical";
}

// The small scene with materials 10^4 times softer than steel and aluminium, a denser
// and hotter inflow and friction: contacts last ~0.1 ms, so the checkpoint holds many
// (about 150 particles of 760 carry a force, 170 history slots are in use, 480 spin)
// and the checks of forces, springs and histories meet real values.
std::string soft_scene() {
  std::string scene = small_scene(true);
  for (const std::string material : {"steel", "aluminium"}) {
    const std::string from = "material = \"" + material + "\"";
    scene.replace(scene.find(from), from.size(), "material = \"soft_" + material + "\"");
  }
  return scene +
         "[materials.soft_steel]\nyoungs_modulus = 2e7\npoisson_ratio = 0.3\ndensity = 7850\n"
         "[materials.soft_aluminium]\nyoungs_modulus = 7e6\npoisson_ratio = 0.33\n"
         "density = 2700\n";
}

TEST(CheckpointFuzz, EveryMutationIsRefusedOrChangesNothing) {
  // 4000 steps, fields sampled every 20 steps from step 2000 (blocks 0-4 by step 3000).
  const StoppedRun run(
      soft_scene(),
      {"time.duration=0.0008", "time.production_start=0.0004", "output.sample_every=20",
       "contact.friction=0.5", "inflow.area_fraction=0.3", "inflow.sigma=0.5"},
      3000, 10);
  const fs::path dir = run.copy("fuzz");
  const std::string pristine = test::read_bytes(run.base() / "checkpoint.h5");
  const std::string pristine_run = test::read_bytes(run.base() / "run.h5");
  std::string failure;
  ASSERT_EQ(outcome(run, dir, failure), "accepted: identical") << failure;

  Rng rng(std::uint64_t(from_environment("GRANSHOCK_FUZZ_SEED", 20240611)));
  const int mutations = int(from_environment("GRANSHOCK_FUZZ_MUTATIONS", kMutations));
  const double seconds = from_environment("GRANSHOCK_FUZZ_SECONDS", kSeconds);
  std::map<std::string, std::map<std::string, int>> counts;
  const auto start = std::chrono::steady_clock::now();
  int done = 0;
  for (; done < mutations; ++done) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > seconds && done >= std::min(kMinimum, mutations)) break;
    // Half raw damage, half edits spread over the seven kinds.
    const Kind kind = done % 2 == 0 ? Kind::raw_bytes : Kind(1 + pick(rng, 7));
    const std::string what = mutate(kind, dir / "checkpoint.h5", pristine, rng);
    const std::string result = outcome(run, dir, failure);
    ++counts[name(kind)][result];
    ASSERT_TRUE(failure.empty()) << "mutation " << done << " (" << name(kind) << ": " << what
                                 << "): " << failure;
    if (result == "accepted: identical") {
      std::printf("[ accepted ] %s: %s\n", name(kind), what.c_str());
      test::write_bytes(dir / "run.h5", pristine_run);
    }
  }
  std::printf("[ fuzzer   ] %d mutations in %.1f s\n", done,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  std::map<std::string, int> totals;
  for (const auto& [kind, results] : counts) {
    std::printf("[ fuzzer   ] %-17s", kind.c_str());
    for (const auto& [result, count] : results) {
      std::printf("  %s %d", result.c_str(), count);
      totals[result] += count;
    }
    std::printf("\n");
  }
  std::printf("[ fuzzer   ] %-17s", "all");
  for (const auto& [result, count] : totals) std::printf("  %s %d", result.c_str(), count);
  std::printf("\n");
}

}  // namespace

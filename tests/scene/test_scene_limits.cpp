// The limits a scene is held to before anything runs (docs/scene_format.md, "Limits"):
// the species count and the pair keys, with the work per pair of species kept at
// O(species^2).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <cstring>
#include <string>

#include "cases/bow_shock/run_checks.hpp"
#include "cases/bow_shock/run_summary.hpp"
#include "cases/collision/head_on_collision.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;

namespace {

// small_scene() with its two species replaced by n (steel and aluminium in turn).
std::string scene_with_species(int n) {
  std::string text = small_scene();
  const auto first = text.find("[[species]]"), contact = text.find("[contact]");
  std::string species;
  for (int k = 0; k < n; ++k)
    species += "[[species]]\nname = \"s" + std::to_string(k) + "\"\nmaterial = \"" +
               (k % 2 ? "aluminium" : "steel") +
               "\"\ndiameter = \"1 d\"\nnumber_fraction = " + fmt::format("{}", 1.0 / n) + "\n";
  return text.replace(first, contact - first, species);
}

std::string refusal(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse_scene(text, sets);
  } catch (const UserError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SceneLimits, AtMost64Species) {
  EXPECT_EQ(parse_scene(scene_with_species(64)).scene.setup.species.size(), 64u);
  EXPECT_EQ(refusal(scene_with_species(65)),
            "scene key 'species' = 65 [[species]] tables: at most 64 species "
            "(docs/scene_format.md, \"Limits\": every pair of species has its own contact "
            "table)");
  // 6,000 species once reached bad_alloc in a dry run: refused before any is read.
  EXPECT_NE(refusal(scene_with_species(6000)).find("= 6000 [[species]] tables: at most 64"),
            std::string::npos);
}

// A species named "obstacle" shared the obstacle's pair keys: contact.pairs.steel-obstacle
// changed the trajectory while the resolved scene still showed the obstacle's 0.5.
TEST(SceneLimits, NoSpeciesMayBeNamedObstacle) {
  EXPECT_EQ(refusal(small_scene(), {"species.1.name=\"obstacle\"",
                                    "contact.pairs.steel-obstacle.restitution=0.9"}),
            "scene key 'species.1.name' = \"obstacle\": a species may not be named \"obstacle\" "
            "(contact.pairs.\"a-obstacle\" names the obstacle) nor \"\"");
}

// A newline in a species name ended as an internal error (exit 3) when the resolved scene's
// TOML was written; a name is printable text, and the message shows the character escaped.
TEST(SceneLimits, NamesHoldNoControlCharacters) {
  EXPECT_EQ(refusal(small_scene(), {"species.0.name=\"st\\neel\""}),
            "scene key 'species.0.name' = \"st\\neel\": a name is 1 to 64 characters, without "
            "control characters (newline, tab, ...)");
  EXPECT_NE(refusal(small_scene(), {"species.0.name=\"a\\tb\""}).find("= \"a\\x09b\""),
            std::string::npos);
  EXPECT_NE(refusal(small_scene(), {"species.0.name=\"" + std::string(65, 'x') + "\""})
                .find("a name is 1 to 64 characters"),
            std::string::npos);
  EXPECT_EQ(refusal(small_scene(), {"species.0.name=\"st,eel \u00e9\""}), "(accepted)");
}

// Dashes stay allowed in names as long as every pair key names one pair.
TEST(SceneLimits, PairKeysThatADashSplitsTwoWaysAreRefused) {
  std::string text = scene_with_species(4);
  const std::vector<std::string> names = {"species.0.name=\"a\"", "species.1.name=\"b-c\"",
                                          "species.2.name=\"a-b\"", "species.3.name=\"c\""};
  EXPECT_EQ(refusal(text, names),
            "scene key 'species.3.name' = \"c\": the pair key \"a-b-c\" would name both a with "
            "b-c and a-b with c; choose species names that no dash can split two ways");
  EXPECT_EQ(refusal(text, {names[0], names[1], names[2], "species.3.name=\"d\""}), "(accepted)");
}

// Labels and sizes of the Kokkos allocations made while a callback is installed.
std::vector<std::uint64_t> g_pair_table_bytes;
void note_allocation(Kokkos::Tools::SpaceHandle, const char* label, const void*, std::uint64_t n) {
  if (std::strcmp(label, "pair_coefficients") == 0) g_pair_table_bytes.push_back(n);
}

// The largest pair table allocated while the summary collides every pair of `scene`.
std::uint64_t largest_pair_table(const Scene& scene, nlohmann::json& table) {
  g_pair_table_bytes.clear();
  Kokkos::Tools::Experimental::set_allocate_data_callback(note_allocation);
  table = effective_restitution_table(scene);
  Kokkos::Tools::Experimental::set_allocate_data_callback(nullptr);
  std::uint64_t largest = 0;
  for (const std::uint64_t n : g_pair_table_bytes) largest = std::max(largest, n);
  return largest;
}

// summary.json collides every pair of species twice; each collision built the whole
// scene's pair table (and copied every pair's settings), O(species^4) in all: 135 s at 200
// species. Each collision now holds its own pair's species alone, with the same result.
TEST(SceneLimits, EachSummaryCollisionHoldsItsOwnPairAlone) {
  const Scene many = parse_scene(scene_with_species(12)).scene;
  const Scene two = parse_scene(scene_with_species(2)).scene;
  nlohmann::json many_table, two_table;
  const std::uint64_t many_bytes = largest_pair_table(many, many_table);
  const std::uint64_t two_bytes = largest_pair_table(two, two_table);
  EXPECT_GT(two_bytes, 0u);
  EXPECT_EQ(many_bytes, two_bytes);
  EXPECT_EQ(many_table.size(), std::size_t(12 * 13 / 2 + 12));
  for (const char* pair : {"s0-s0", "s0-s1", "s1-s1", "s0-obstacle", "s1-obstacle"})
    EXPECT_EQ(many_table[pair], two_table[pair]) << pair;
  // The table collides on the serial backend: the same numbers as the default one's.
  const CollisionResult r =
      collide_species(many.setup, 5, 8, many.inflow.speed_m_per_s, many.setup.dt, true);
  EXPECT_EQ(many_table["s5-s8"]["at_inflow_speed"]["e_eff"].get<double>(), r.e_eff);
}

// A pair whose restitution summary.json cannot measure at the run's dt (e = 1e-6 stays in
// contact past the collision's bound) ran the whole simulation, then ended without a
// summary. The same measurement is made before the run (here on a scene the schema's range
// would refuse, to reach it).
TEST(SceneLimits, APairSummaryCannotMeasureIsRefusedBeforeTheRun) {
  Scene s = parse_scene(small_scene()).scene;
  s.setup.contacts = ContactSettings::uniform(2, 1e-6, 0.0);
  try {
    check_scene_before_run(s, false);
    FAIL() << "accepted";
  } catch (const UserError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("scene keys 'contact.restitution' / 'time.dt': the effective "
                         "restitution of the pairs at this step cannot be measured",
                         0),
              0u)
        << what;
    EXPECT_NE(what.find("did not complete within"), std::string::npos) << what;
  }
}

}  // namespace

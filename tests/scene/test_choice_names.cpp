// Every name of every choice (core/choice_names.hpp, core/variant_names.hpp) goes through
// every place that reads or writes it: parse and write back, the per-choice parse and
// to_string functions, the scene schema (accepted, stored, echoed in the resolved scene
// that run.h5 and the checkpoint keep, read back the same), docs/scene_keys.md's list,
// and for contact laws the compiled law of that name. The command line and the files of a
// run are checked by tests/cli/every_choice_name.sh. A name missing in any of them fails
// here: the `hooke` that `to_string` gave every law but hertz would.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>

#include "core/choice_names.hpp"
#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "kernels/models/models.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;

namespace {

template <class Enum>
class ChoiceTable : public ::testing::Test {};
using EveryChoice =
    ::testing::Types<ContactModelKind, RestitutionMode, Precision, ScatterStrategy, MassDefinition,
                     MachReference, SlabAxis, SlabBalance, SnapshotOutput, BackendSwitchMode,
                     ObstacleShape, ImpactLine, BatchScript, ZBoundary>;
TYPED_TEST_SUITE(ChoiceTable, EveryChoice);

TYPED_TEST(ChoiceTable, EveryNameParsesToItsValueAndBack) {
  for (const ChoiceName<TypeParam>& c : Choices<TypeParam>::table) {
    EXPECT_EQ(parse_choice<TypeParam>(c.name), c.value) << c.name;
    EXPECT_STREQ(choice_name(c.value), c.name);
    EXPECT_STRNE(c.description, "") << c.name;
  }
}

TYPED_TEST(ChoiceTable, AnUnknownNameIsRefusedNamingEveryValidOne) {
  try {
    parse_choice<TypeParam>("no-such-name");
    FAIL() << "accepted";
  } catch (const UserError& e) {
    std::string expected = std::string(Choices<TypeParam>::what) + " 'no-such-name' is not one of ";
    for (const ChoiceName<TypeParam>& c : Choices<TypeParam>::table)
      expected += std::string(c.value == Choices<TypeParam>::table[0].value ? "" : ", ") + c.name;
    EXPECT_EQ(e.what(), expected);
  }
}

// The functions the rest of the code calls (core/solver_setup.cpp, kinetic_theory.cpp,
// scene.cpp): the `to_string` that wrote "hooke" for any law but hertz.
TEST(ChoiceNames, TheNamedParseAndToStringFunctionsFollowTheTables) {
  for (const auto& c : Choices<ContactModelKind>::table) {
    EXPECT_EQ(to_string(c.value), c.name);
    EXPECT_EQ(parse_contact_model(c.name), c.value) << c.name;
  }
  for (const auto& c : Choices<RestitutionMode>::table) {
    EXPECT_EQ(to_string(c.value), c.name);
    EXPECT_EQ(parse_restitution_mode(c.name), c.value) << c.name;
  }
  for (const auto& c : Choices<MassDefinition>::table) {
    EXPECT_EQ(to_string(c.value), c.name);
    EXPECT_EQ(parse_mass_definition(c.name), c.value) << c.name;
  }
  for (const auto& c : Choices<MachReference>::table) {
    EXPECT_EQ(to_string(c.value), c.name);
    EXPECT_EQ(parse_mach_reference(c.name), c.value) << c.name;
  }
}

// Every contact model has the compiled law of its name (kernels/models/models.hpp, which
// also asserts this at compile time), and with_contact_model picks it.
TEST(ChoiceNames, EveryContactModelIsTheCompiledLawOfItsName) {
  for (const auto& c : Choices<ContactModelKind>::table) {
    const auto law = with_contact_model(c.value, [](auto l) {
      return std::make_pair(decltype(l)::kind, std::string(decltype(l)::name));
    });
    EXPECT_EQ(law.first, c.value) << c.name;
    EXPECT_EQ(law.second, c.name);
  }
}

// A scene key whose value is a choice: its table's names, the value the scene read, and
// whether the resolved scene writes it back (inflow.mach_at is written as the sigma found).
struct ChoiceKey {
  std::vector<std::string> names;
  std::function<std::string(const Scene&)> value;
  bool echoed = true;
  std::vector<std::string> also = {};  // overrides the key needs beside it
  std::string drop = {};               // a line of small_scene() it replaces
  std::map<std::string, std::vector<std::string>> also_for = {};  // overrides one name needs
};

template <class Enum, class Field>
ChoiceKey choice_key(Field field) {
  return {choice_names<Enum>(), [field](const Scene& s) { return choice_name(field(s)); }};
}

const std::map<std::string, ChoiceKey>& choice_keys() {
  static const std::map<std::string, ChoiceKey> keys = [] {
    std::map<std::string, ChoiceKey> k;
    k["contact.model"] =
        choice_key<ContactModelKind>([](const Scene& s) { return s.setup.contacts.model; });
    // Each law has its own parameter keys (models/law_parameters.hpp).
    k["contact.model"].also_for = {{"linear", {"contact.stiffness=1e5"}}};
    k["contact.restitution_mode"] = choice_key<RestitutionMode>(
        [](const Scene& s) { return s.setup.contacts.restitution_mode; });
    k["numerics.precision"] =
        choice_key<Precision>([](const Scene& s) { return s.setup.precision; });
    k["numerics.field_scatter"] =
        choice_key<ScatterStrategy>([](const Scene& s) { return s.field_scatter; });
    k["numerics.mass_definition"] =
        choice_key<MassDefinition>([](const Scene& s) { return s.mass_definition; });
    k["inflow.mach_at"] =
        choice_key<MachReference>([](const Scene& s) { return s.inflow.mach_at; });
    k["inflow.mach_at"].echoed = false;
    k["inflow.mach_at"].also = {"inflow.mach=7.5"};
    k["inflow.mach_at"].drop = "sigma = 0.1\n";
    k["domain.z_boundary"] = choice_key<ZBoundary>(
        [](const Scene& s) { return s.setup.z_walls ? ZBoundary::walls : ZBoundary::periodic; });
    k["domain.z_boundary"].also = {"scene.dim=3", "domain.thickness=\"4 d\""};
    // Each shape has its own size keys (docs/scene_keys.md, [obstacle]).
    k["obstacle.shape"] =
        choice_key<ObstacleShape>([](const Scene& s) { return s.setup.obstacle->shape; });
    k["obstacle.shape"].drop = "diameter = \"10 d\"\n";
    k["obstacle.shape"].also_for = {
        {"cylinder", {"obstacle.diameter=\"10 d\""}},
        {"wedge", {"obstacle.half_angle=20", "obstacle.length=\"10 d\""}},
        {"plate", {"obstacle.width=\"10 d\"", "obstacle.thickness=\"2 d\""}},
        {"square", {"obstacle.side=\"8 d\""}},
        {"sphere", {"obstacle.diameter=\"10 d\""}}};
    return k;
  }();
  return keys;
}

std::string leaf(const std::string& key) {
  return key.substr(key.rfind('.') + 1);
}

TEST(ChoiceNames, TheSceneAcceptsEchoesAndReadsBackEveryName) {
  for (const auto& [key, choice] : choice_keys()) {
    for (const std::string& name : choice.names) {
      SCOPED_TRACE(key + " = " + name);
      std::string text = small_scene();
      if (!choice.drop.empty()) text.erase(text.find(choice.drop), choice.drop.size());
      std::vector<std::string> overrides = choice.also;
      if (choice.also_for.count(name))
        for (const std::string& o : choice.also_for.at(name)) overrides.push_back(o);
      overrides.push_back(key + "=\"" + name + "\"");
      const LoadedScene given = parse_scene(text, overrides);
      EXPECT_EQ(choice.value(given.scene), name);
      // The resolved scene is what run.h5 and the checkpoint keep (docs/output_format.md).
      const LoadedScene back = parse_scene(given.resolved, {}, "the resolved scene");
      if (choice.echoed) {
        EXPECT_NE(given.resolved.find("\n" + leaf(key) + " = '" + name + "'\n"), std::string::npos)
            << given.resolved;
        EXPECT_EQ(choice.value(back.scene), name);
      }
    }
  }
}

TEST(ChoiceNames, TheSceneRefusesAnUnknownNameListingTheTablesNames) {
  for (const auto& [key, choice] : choice_keys()) {
    SCOPED_TRACE(key);
    std::string list;
    for (const std::string& n : choice.names) list += (list.empty() ? "" : ", ") + n;
    std::string text = small_scene();  // with what the key needs beside it
    if (!choice.drop.empty()) text.erase(text.find(choice.drop), choice.drop.size());
    std::vector<std::string> overrides = choice.also;
    overrides.push_back(key + "=\"no-such-name\"");
    try {
      parse_scene(text, overrides);
      ADD_FAILURE() << "accepted";
    } catch (const UserError& e) {
      EXPECT_EQ(std::string(e.what()),
                "scene key '" + key + "' = \"no-such-name\": must be one of " + list);
    }
  }
}

// docs/scene_keys.md ("Keys"): the valid values of each choice key are the table's names.
TEST(ChoiceNames, TheDocsListEveryNameOfEveryChoiceKey) {
  std::ifstream in(std::filesystem::path(GRANSHOCK_SOURCE_DIR) / "docs" / "scene_keys.md");
  ASSERT_TRUE(in) << "docs/scene_keys.md";
  std::map<std::string, std::string> documented;  // key -> its column of valid values
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::size_t from = 1;
    for (std::size_t bar; (bar = line.find(" |", from)) != std::string::npos; from = bar + 2)
      cells.push_back(line.substr(from + 1, bar - from - 1));
    if (cells.size() >= 4) documented[cells[0].substr(1, cells[0].size() - 2)] = cells[3];
  }
  for (const auto& [key, choice] : choice_keys()) {
    std::string list;
    for (const std::string& n : choice.names) list += (list.empty() ? "" : ", ") + n;
    ASSERT_TRUE(documented.count(key)) << key << " is not in docs/scene_keys.md";
    EXPECT_EQ(documented[key], list) << "the valid values of " << key;
  }
}

// Every scene key of type string that is not a name of the user's own (scene.name, species
// and material names) is a choice this test covers.
TEST(ChoiceNames, EveryChoiceKeyOfTheSchemaIsCovered) {
  const std::vector<std::string> free_names = {"scene.name", "[[species]] name",
                                               "[[species]] material", "obstacle.material"};
  for (const SceneKey& k : scene_keys()) {
    if (k.type == "string" &&
        std::find(free_names.begin(), free_names.end(), k.name) == free_names.end()) {
      EXPECT_TRUE(choice_keys().count(k.name)) << k.name << ": add it to choice_keys()";
    }
  }
}

}  // namespace

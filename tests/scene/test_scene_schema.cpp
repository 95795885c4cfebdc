// The scene schema (io/scene_schema_*.cpp) declares each key once, for reading and for
// writing the resolved scene. For every key of the schema: a scene given a non-default
// value of it, written back and read again, is the same Scene field by field, and the
// written scene holds the value under the key's own name. And docs/scene_keys.md
// ("Keys") documents exactly the schema's keys, with the schema's types.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/user_error.hpp"
#include "io/scene_file.hpp"
#include "models/law_parameters.hpp"
#include "scene_fixtures.hpp"

using namespace granshock;
using granshock::testing::small_scene;

namespace {

// A value for a key that differs from small_scene(): --set overrides, after dropping a
// line of small_scene() (inflow.mach replaces inflow.sigma).
struct NonDefault {
  std::vector<std::string> overrides;
  std::string drop = {};
};

// One entry per key of the schema (SceneSchema.EveryKeyHasANonDefaultValue).
const std::map<std::string, NonDefault>& non_default_values() {
  static const std::map<std::string, NonDefault> values = {
      {"scene.name", {{"scene.name=\"other\""}}},
      {"scene.dim", {{"scene.dim=3", "domain.thickness=\"2 d\""}}},
      {"scene.seed", {{"scene.seed=12345"}}},
      {"units.d", {{"units.d=0.002"}}},
      {"materials.NAME.youngs_modulus",
       {{"materials.steel.youngs_modulus=1e11", "materials.steel.poisson_ratio=0.303",
         "materials.steel.density=7850.0"}}},
      {"materials.NAME.poisson_ratio",
       {{"materials.steel.youngs_modulus=210e9", "materials.steel.poisson_ratio=0.25",
         "materials.steel.density=7850.0"}}},
      {"materials.NAME.density",
       {{"materials.steel.youngs_modulus=210e9", "materials.steel.poisson_ratio=0.303",
         "materials.steel.density=8000.0"}}},
      // A dash in a species name: the pairs "steel-alu-2", "alu-2-alu-2" and
      // "alu-2-obstacle" of the resolved scene must be read back as such.
      {"[[species]] name", {{"species.1.name=\"alu-2\""}}},
      {"[[species]] material", {{"species.0.material=\"aluminium\""}}},
      {"[[species]] diameter", {{"species.1.diameter=\"1.5 d\""}}},
      {"[[species]] number_fraction",
       {{"species.0.number_fraction=0.25", "species.1.number_fraction=0.75"}}},
      {"contact.restitution", {{"contact.restitution=0.8"}}},
      {"contact.friction", {{"contact.friction=0.3"}}},
      {"contact.model", {{"contact.model=\"hooke\""}}},
      {"contact.limit_force", {{"contact.limit_force=true"}}},
      {"contact.characteristic_velocity",
       {{"contact.model=\"hooke\"", "contact.characteristic_velocity=3.5"}}},
      {"contact.stiffness", {{"contact.model=\"linear\"", "contact.stiffness=2e5"}}},
      {"contact.restitution_mode", {{"contact.restitution_mode=\"discrete\""}}},
      {"contact.calibration_speed", {{"contact.calibration_speed=2.5"}}},
      {"contact.softening", {{"contact.softening=1000"}}},
      {"contact.pairs.\"a-b\".restitution",
       {{"contact.pairs.steel-aluminium.restitution=0.9",
         "contact.pairs.aluminium-obstacle.restitution=0.7"}}},
      {"contact.pairs.\"a-b\".friction",
       {{"contact.pairs.steel-steel.friction=0.2", "contact.pairs.steel-obstacle.friction=0.4"}}},
      {"domain.width", {{"domain.width=\"50 d\""}}},
      {"domain.length", {{"domain.length=\"70 d\""}}},
      {"domain.thickness", {{"scene.dim=3", "domain.thickness=\"3 d\""}}},
      {"domain.z_boundary",
       {{"scene.dim=3", "domain.thickness=\"4 d\"", "domain.z_boundary=\"periodic\""}}},
      {"obstacle.diameter", {{"obstacle.diameter=\"12 d\""}}},
      {"obstacle.shape",
       {{"obstacle.shape=\"plate\"", "obstacle.width=\"12 d\"", "obstacle.thickness=\"2 d\""},
        "diameter = \"10 d\"\n"}},
      {"obstacle.half_angle",
       {{"obstacle.shape=\"wedge\"", "obstacle.half_angle=25", "obstacle.length=\"10 d\""},
        "diameter = \"10 d\"\n"}},
      {"obstacle.length",
       {{"obstacle.shape=\"wedge\"", "obstacle.half_angle=20", "obstacle.length=\"12 d\""},
        "diameter = \"10 d\"\n"}},
      {"obstacle.width",
       {{"obstacle.shape=\"plate\"", "obstacle.width=\"8 d\"", "obstacle.thickness=\"3 d\""},
        "diameter = \"10 d\"\n"}},
      {"obstacle.thickness",
       {{"obstacle.shape=\"plate\"", "obstacle.width=\"8 d\"", "obstacle.thickness=\"1 d\""},
        "diameter = \"10 d\"\n"}},
      {"obstacle.side",
       {{"obstacle.shape=\"square\"", "obstacle.side=\"9 d\""}, "diameter = \"10 d\"\n"}},
      {"obstacle.rotation",
       {{"obstacle.shape=\"square\"", "obstacle.side=\"6 d\"", "obstacle.rotation=30"},
        "diameter = \"10 d\"\n"}},
      {"obstacle.centre", {{"obstacle.centre=[\"18 d\", \"30 d\"]"}}},
      {"obstacle.material", {{"obstacle.material=\"steel\""}}},
      {"inflow.area_fraction", {{"inflow.area_fraction=0.2"}}},
      {"inflow.velocity", {{"inflow.velocity=2.5"}}},
      {"inflow.sigma", {{"inflow.sigma=0.05"}}},
      {"inflow.mach", {{"inflow.mach=7.5"}, "sigma = 0.1\n"}},
      // The calibration runs with the run, not the parser: here sigma is the first guess.
      {"inflow.mach_at", {{"inflow.mach=7.5", "inflow.mach_at=\"inlet_bins\""}, "sigma = 0.1\n"}},
      {"inflow.strip", {{"inflow.strip=\"3 d\""}}},
      {"time.dt", {{"time.dt=1e-7"}}},
      {"time.duration", {{"time.duration=0.02"}}},
      {"time.production_start", {{"time.production_start=0.002"}}},
      {"output.snapshot_interval", {{"output.snapshot_interval=0.001"}}},
      {"output.series_interval", {{"output.series_interval=0.0002"}}},
      {"output.checkpoint_interval", {{"output.checkpoint_interval=0.002"}}},
      {"output.progress_interval", {{"output.progress_interval=3.0"}}},
      {"output.sample_every", {{"output.sample_every=20"}}},
      {"output.blocks", {{"output.blocks=4"}}},
      {"numerics.precision", {{"numerics.precision=\"single\""}}},
      {"numerics.skin", {{"numerics.skin=\"0.5 d\""}}},
      {"numerics.adaptive_skin", {{"numerics.adaptive_skin=true"}}},
      {"numerics.mass_definition", {{"numerics.mass_definition=\"paper_sum\""}}},
      {"numerics.bin_size", {{"numerics.bin_size=\"4 d\""}}},
      {"numerics.field_scatter", {{"numerics.field_scatter=\"scatter_view\""}}},
  };
  return values;
}

// The fields of two scenes that differ, by name; every field of Scene is compared. The
// fluctuation is compared as it is used (inflow.sigma): a Mach number is written back as
// the sigma it gives, so target_mach and sigma_m_per_s say only how the scene gave it.
class Differences {
 public:
  template <class T>
  void operator()(const std::string& name, const T& a, const T& b) {
    if (!(a == b)) names.push_back(name);
  }
  void material(const std::string& name, const Material& a, const Material& b) {
    (*this)(name + ".name", a.name, b.name);
    (*this)(name + ".youngs_modulus_pa", a.youngs_modulus_pa, b.youngs_modulus_pa);
    (*this)(name + ".poisson_ratio", a.poisson_ratio, b.poisson_ratio);
    (*this)(name + ".density_kg_m3", a.density_kg_m3, b.density_kg_m3);
  }
  std::vector<std::string> names;
};

std::vector<std::string> differences(const Scene& a, const Scene& b) {
  Differences d;
  d("name", a.name, b.name);
  d("d_m", a.d_m, b.d_m);
  d("mass_definition", a.mass_definition, b.mass_definition);
  d("bin_size_m", a.bin_size_m, b.bin_size_m);
  d("field_scatter", a.field_scatter, b.field_scatter);

  const SolverSetup &sa = a.setup, &sb = b.setup;
  d("setup.dim", sa.dim, sb.dim);
  d("setup.box.lo", sa.box.lo, sb.box.lo);
  d("setup.box.hi", sa.box.hi, sb.box.hi);
  d("setup.box.periodic", sa.box.periodic, sb.box.periodic);
  d("setup.z_walls", sa.z_walls, sb.z_walls);
  d("setup.wall_material", sa.wall_material.name, sb.wall_material.name);
  d("setup.species.size", sa.species.size(), sb.species.size());
  for (std::size_t i = 0; i < std::min(sa.species.size(), sb.species.size()); ++i) {
    const std::string n = "setup.species." + std::to_string(i);
    d(n + ".name", sa.species[i].name, sb.species[i].name);
    d.material(n + ".material", sa.species[i].material, sb.species[i].material);
    d(n + ".diameter_m", sa.species[i].diameter_m, sb.species[i].diameter_m);
  }
  const ContactSettings &ca = sa.contacts, &cb = sb.contacts;
  d("setup.contacts.model", ca.model, cb.model);
  d("setup.contacts.options.limit_force", ca.options.limit_force, cb.options.limit_force);
  for (int k = 0; k < kMaxLawParameters; ++k)
    d("setup.contacts.options.law_parameters[" + std::to_string(k) + "]",
      ca.options.law_parameters[k], cb.options.law_parameters[k]);
  d("setup.contacts.restitution_mode", ca.restitution_mode, cb.restitution_mode);
  d("setup.contacts.calibration_speed_m_per_s", ca.calibration_speed_m_per_s,
    cb.calibration_speed_m_per_s);
  d("setup.contacts.softening", ca.softening, cb.softening);
  d("setup.contacts.restitution", ca.restitution, cb.restitution);
  d("setup.contacts.friction", ca.friction, cb.friction);
  d("setup.contacts.obstacle_restitution", ca.obstacle_restitution, cb.obstacle_restitution);
  d("setup.contacts.obstacle_friction", ca.obstacle_friction, cb.obstacle_friction);
  d("setup.obstacle.has_value", sa.obstacle.has_value(), sb.obstacle.has_value());
  if (sa.obstacle && sb.obstacle) {
    d("setup.obstacle.shape", sa.obstacle->shape, sb.obstacle->shape);
    d("setup.obstacle.centre", sa.obstacle->centre, sb.obstacle->centre);
    for (int k = 0; k < kMaxShapeSizes; ++k)
      d("setup.obstacle.size[" + std::to_string(k) + "]", sa.obstacle->size[k],
        sb.obstacle->size[k]);
    d.material("setup.obstacle.material", sa.obstacle->material, sb.obstacle->material);
  }
  d("setup.dt", sa.dt, sb.dt);
  d("setup.skin_m", sa.skin_m, sb.skin_m);
  d("setup.adaptive_skin", sa.adaptive_skin, sb.adaptive_skin);
  d("setup.gravity", sa.gravity, sb.gravity);
  d("setup.precision", sa.precision, sb.precision);
  d("setup.delete_outside", sa.delete_outside, sb.delete_outside);

  d("inflow.area_fraction", a.inflow.area_fraction, b.inflow.area_fraction);
  d("inflow.speed_m_per_s", a.inflow.speed_m_per_s, b.inflow.speed_m_per_s);
  d("inflow.sigma", a.inflow.sigma, b.inflow.sigma);
  d("inflow.strip_m", a.inflow.strip_m, b.inflow.strip_m);
  d("inflow.number_fraction", a.inflow.number_fraction, b.inflow.number_fraction);

  d("run.duration_s", a.run.duration_s, b.run.duration_s);
  d("run.production_start_s", a.run.production_start_s, b.run.production_start_s);
  d("run.snapshot_interval_s", a.run.snapshot_interval_s, b.run.snapshot_interval_s);
  d("run.series_interval_s", a.run.series_interval_s, b.run.series_interval_s);
  d("run.checkpoint_interval_s", a.run.checkpoint_interval_s, b.run.checkpoint_interval_s);
  d("run.progress_interval_s", a.run.progress_interval_s, b.run.progress_interval_s);
  d("run.sample_every", a.run.sample_every, b.run.sample_every);
  d("run.blocks", a.run.blocks, b.run.blocks);
  d("run.seed", a.run.seed, b.run.seed);
  return d.names;
}

std::vector<std::string> segments(const std::string& dotted) {
  std::vector<std::string> out;
  std::istringstream in(dotted);
  for (std::string part; std::getline(in, part, '.');) out.push_back(part);
  return out;
}

// Whether a dotted key of a resolved scene ("species.1.diameter") is the documented key
// ("[[species]] diameter"), or an element of it: NAME, "a-b" and the index of [[species]]
// stand for any name.
// inflow.mach (and mach_at) are written back as the inflow.sigma they give.
bool written_as(const std::string& documented, const std::string& key) {
  if (documented == "inflow.mach" || documented == "inflow.mach_at") return key == "inflow.sigma";
  const std::string species = "[[species]] ";
  std::vector<std::string> pattern =
      documented.rfind(species, 0) == 0
          ? std::vector<std::string>{"species", "*", documented.substr(species.size())}
          : segments(documented);
  std::vector<std::string> parts = segments(key);
  if (parts.size() == pattern.size() + 1 &&
      parts.back().find_first_not_of("0123456789") == std::string::npos)
    parts.pop_back();  // an element of an array ("obstacle.centre.0")
  if (parts.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (pattern[i] != "*" && pattern[i] != "NAME" && pattern[i] != "\"a-b\"" &&
        pattern[i] != parts[i])
      return false;
  return true;
}

std::string test_name(const std::string& key) {
  std::string name;
  for (char c : key) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      name += c;
    else if (!name.empty() && name.back() != '_')
      name += '_';
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

namespace granshock {
// How GoogleTest shows a parameter: the key's name.
void PrintTo(const SceneKey& key, std::ostream* os) {
  *os << key.name;
}
}  // namespace granshock

class SceneKeyRoundTrip : public ::testing::TestWithParam<SceneKey> {};

TEST_P(SceneKeyRoundTrip, ParseOfWriteGivesTheSameScene) {
  const std::string& key = GetParam().name;
  const auto value = non_default_values().find(key);
  ASSERT_NE(value, non_default_values().end())
      << "no non-default value for '" << key << "': add one to non_default_values()";
  std::string text = small_scene();
  if (!value->second.drop.empty()) {
    const auto at = text.find(value->second.drop);
    ASSERT_NE(at, std::string::npos);
    text.erase(at, value->second.drop.size());
  }
  const LoadedScene base = parse_scene(small_scene());
  const LoadedScene given = parse_scene(text, value->second.overrides);
  const LoadedScene back = parse_scene(given.resolved, {}, "the resolved scene");

  EXPECT_EQ(joined(differences(given.scene, back.scene)), "")
      << "fields lost between the scene and its resolved text:\n"
      << given.resolved;
  EXPECT_EQ(back.resolved, given.resolved);
  EXPECT_NE(joined(differences(base.scene, given.scene)), "")
      << "the value given to '" << key << "' changes no field this test compares";
  const std::vector<std::string> changed = differing_keys(base.resolved, given.resolved);
  EXPECT_TRUE(std::any_of(changed.begin(), changed.end(),
                          [&](const std::string& k) { return written_as(key, k); }))
      << "'" << key << "' is not written back under its name; changed keys: " << joined(changed);
}

INSTANTIATE_TEST_SUITE_P(EveryKey, SceneKeyRoundTrip, ::testing::ValuesIn(scene_keys()),
                         [](const auto& param_info) { return test_name(param_info.param.name); });

TEST(SceneSchema, EveryKeyHasANonDefaultValue) {
  std::vector<std::string> keys, stale;
  for (const SceneKey& k : scene_keys()) keys.push_back(k.name);
  for (const auto& [name, value] : non_default_values())
    if (std::find(keys.begin(), keys.end(), name) == keys.end()) stale.push_back(name);
  EXPECT_EQ(joined(stale), "") << "values for keys the schema does not have";
  EXPECT_EQ(keys.size(), non_default_values().size());
}

// The "Keys" table of docs/scene_keys.md is the one the schema makes (`granshock keys`):
// every key, type, unit, range, default and meaning as the program has them (the
// defaults and ranges are checked against the program by tests/docs/check_scene_keys.py).
TEST(SceneSchema, TheDocsTableIsTheOneTheSchemaMakes) {
  std::ifstream in(std::filesystem::path(GRANSHOCK_SOURCE_DIR) / "docs" / "scene_keys.md");
  ASSERT_TRUE(in) << "docs/scene_keys.md";
  std::vector<std::string> documented;
  bool in_keys = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) in_keys = line == "## Keys";
    if (in_keys && line.rfind("|", 0) == 0) documented.push_back(line);
  }
  std::vector<std::string> generated;
  std::istringstream table(scene_keys_table());
  for (std::string line; std::getline(table, line);) generated.push_back(line);
  ASSERT_GT(generated.size(), 40u) << "the schema's table has too few rows";
  const std::string fix = "; make it again: cmake --build build --target scene_keys_doc";
  for (std::size_t i = 0; i < std::min(documented.size(), generated.size()); ++i)
    ASSERT_EQ(documented[i], generated[i]) << "docs/scene_keys.md, row " << i << fix;
  EXPECT_EQ(documented.size(), generated.size()) << "rows in docs/scene_keys.md" << fix;
}

// Every key's row says something: a unit where its type has one, an accepted range or
// rule except for a bool, a default, and what it does.
TEST(SceneSchema, EveryKeyIsDocumentedWhereItIsDeclared) {
  for (const SceneKey& k : scene_keys()) {
    EXPECT_FALSE(k.doc.fallback.empty()) << k.name << ": no default (nor \"required\")";
    if (k.type != "bool") {
      EXPECT_FALSE(k.doc.accepted.empty()) << k.name << ": nothing accepted";
    }
    if (k.type.find('(') != std::string::npos || k.type.find("length") != std::string::npos) {
      EXPECT_FALSE(k.doc.unit.empty()) << k.name << ": its type " << k.type << " has a unit";
    }
    EXPECT_FALSE(k.doc.meaning.empty()) << k.name << ": no meaning";
  }
}

// Pair names split at the dash that leaves two known species; an unknown species is
// named as before (the part after the first dash).
TEST(SceneSchema, PairsOfSpeciesWhoseNamesHoldADash) {
  const Scene s = parse_scene(small_scene(), {"species.1.name=\"alu-2\"",
                                              "contact.pairs.alu-2-obstacle.restitution=0.7",
                                              "contact.pairs.steel-alu-2.friction=0.2"})
                      .scene;
  EXPECT_EQ(s.setup.contacts.obstacle_restitution, (std::vector<double>{0.5, 0.7}));
  EXPECT_EQ(s.setup.contacts.friction[0][1], 0.2);
  EXPECT_EQ(s.setup.contacts.friction[1][0], 0.2);
  try {
    parse_scene(small_scene(), {"contact.pairs.steel-copper.friction=0.2"});
    FAIL() << "an unknown species was accepted";
  } catch (const UserError& e) {
    EXPECT_STREQ(e.what(), "scene key 'contact.pairs.steel-copper' = \"copper\": unknown species");
  }
}

// Each contact law takes only its own parameter keys (models/law_parameters.hpp):
// another law's key is refused naming the key and its law, a required one missing is
// refused naming it, and the resolved scene holds the law's keys alone.
TEST(SceneSchema, ALawTakesOnlyItsOwnKeys) {
  const auto refusal = [](const std::vector<std::string>& sets) -> std::string {
    try {
      parse_scene(small_scene(), sets);
    } catch (const UserError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(refusal({"contact.characteristic_velocity=2.0"}),
            "scene key 'contact.characteristic_velocity' = 2.0: is a key of contact.model = "
            "\"hooke\", and the model is \"hertz\"");
  EXPECT_EQ(refusal({"contact.model=\"hooke\"", "contact.stiffness=1e5"}),
            "scene key 'contact.stiffness' = 100000.0: is a key of contact.model = \"linear\", "
            "and the model is \"hooke\"");
  EXPECT_NE(refusal({"contact.model=\"linear\""}).find("contact.stiffness"), std::string::npos);
  EXPECT_NE(refusal({"contact.model=\"linear\"", "contact.stiffness=1e13"})
                .find("scene key 'contact.stiffness' = 10000000000000: must be in [0.001, 1e+12]"),
            std::string::npos);
  const LoadedScene linear =
      parse_scene(small_scene(), {"contact.model=\"linear\"", "contact.stiffness=1e5"});
  EXPECT_EQ(LinearParameters::stiffness(linear.scene.setup.contacts.options), 1e5);
  EXPECT_NE(linear.resolved.find("stiffness = 1e+05"), std::string::npos);
  EXPECT_EQ(linear.resolved.find("characteristic_velocity"), std::string::npos);
  const LoadedScene hooke = parse_scene(small_scene(), {"contact.model=\"hooke\""});
  EXPECT_EQ(HookeParameters::characteristic_velocity(hooke.scene.setup.contacts.options),
            hooke.scene.inflow.speed_m_per_s);  // the default: the inflow speed
  EXPECT_NE(hooke.resolved.find("characteristic_velocity"), std::string::npos);
  const LoadedScene hertz = parse_scene(small_scene());
  EXPECT_EQ(hertz.resolved.find("characteristic_velocity"), std::string::npos);
  EXPECT_EQ(hertz.resolved.find("stiffness"), std::string::npos);
}

// A checkpoint of a granshock from before each law owned its keys stored a hertz scene
// with contact.characteristic_velocity, which today's reader refuses: a resume reads it
// without that key (io/scene_file.hpp, without_other_laws_keys), and finds no difference
// from the same scene resolved today. A law's own key stays.
TEST(SceneSchema, AnOlderResolvedSceneLosesOnlyAnotherLawsKeys) {
  const LoadedScene today = parse_scene(small_scene());
  std::string older = today.resolved;
  const std::size_t contact = older.find("[contact]\n");
  ASSERT_NE(contact, std::string::npos);
  older.insert(contact + 10, "characteristic_velocity = 1.0\n");
  EXPECT_THROW(parse_scene(older), UserError);
  const std::string read = without_other_laws_keys(older);
  EXPECT_EQ(read.find("characteristic_velocity"), std::string::npos);
  EXPECT_NO_THROW(parse_scene(read));
  EXPECT_TRUE(differing_keys(read, today.resolved).empty());
  EXPECT_EQ(without_other_laws_keys(today.resolved), today.resolved);  // nothing to remove
  const LoadedScene hooke = parse_scene(small_scene(), {"contact.model=\"hooke\""});
  EXPECT_EQ(without_other_laws_keys(hooke.resolved), hooke.resolved);
}

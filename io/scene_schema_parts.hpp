// What the scene schema's files share (io/scene_schema.cpp, the machinery and the assembled
// schema; io/scene_schema_*.cpp, the sections): the key and table types, the ranges of the
// scene's numbers, and each section's table.
#pragma once

#include <fmt/format.h>

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/choice_names.hpp"
#include "core/scene.hpp"
#include "io/scene_file.hpp"
#include "io/scene_schema.hpp"
#include "io/table_reader.hpp"
#include "models/law_parameters.hpp"

namespace granshock::scene_toml::schema_detail {

// Physical ranges of the scene's numbers (docs/scene_keys.md): values outside
// them passed every check and failed late, as -nan particle counts (units.d = 1e-320),
// a diameter of 1e-320 m, or a restitution of 1e-6 that ran the whole simulation before
// its effective restitution could not be measured.
struct Range {
  double lo, hi;
  const char* why;
};
// Particle sizes (and the unit d): micrometre powders to metre boulders.
inline constexpr Range kDiameter = {1e-6, 1.0, "from a micrometre powder to a metre boulder"};
inline constexpr Range kYoungsModulus = {1e3, 1e13, "from a hydrogel to past diamond's 1.2e12 Pa"};
inline constexpr Range kDensity = {1.0, 1e5, "from an aerogel to past osmium's 22590 kg/m3"};
// Below 0.01 the damped Hertz law's rebound creeps: a contact lasts 2.7 t_c at e = 0.01 and
// 25 t_c at e = 1e-6, and the integrator at the usual steps returns under half of e
// (docs/contact_model.md, "Restitution range").
inline constexpr Range kRestitution = {
    0.01, 1.0,
    "below 0.01 the damped contact law's rebound is not resolved (docs/contact_model.md)"};
inline constexpr Range kFriction = {0.0, 10.0, "Coulomb friction of real materials is below 2"};
// Speeds: the inflow, its fluctuation and the speeds contacts are calibrated at.
inline constexpr Range kSpeed = {1e-6, 1e4, "from a micrometre per second to hypervelocity"};
inline constexpr Range kSigma = {0.0, 1e4, "at most hypervelocity"};
inline constexpr Range kMach = {0.1, 1e4, "from a subsonic to a hypersonic gas"};
inline constexpr Range kSoftening = {1.0, 1e9,
                                     "every modulus divided by this stays at least 1e-9 of it"};
inline constexpr Range kNumberFraction = {1e-6, 1.0, "at least one particle in a million"};
inline constexpr double kMinAreaFraction = 1e-6;
// The domain's extent: positions are double, resolved to 2e-12 m at 10 km.
inline constexpr double kMaxDomainLength = 1e4;
inline constexpr Range kProgressInterval = {0.01, 1e9, "wall-clock seconds"};

// A number as docs/scene_keys.md writes it, the shorter of plain and exponent form (plain
// on a tie): 1e-6, 1e4, 0.5, 90 (not 1e-06, 10000).
std::string short_number(double value);
// The unit a key's type names: "N/m" of "number (N/m)"; none for a plain "number".
std::string unit_of_type(const std::string& type);

// A key whose value is a name of Choices<Enum> (core/choice_names.hpp): the table's names
// are the accepted ones, `fallback` the default.
template <class Enum>
Enum read_choice(TableReader& r, const std::string& k, Enum fallback) {
  return parse_choice<Enum>(r.choice(k, choice_names<Enum>(), choice_name(fallback)));
}

// What the keys of a table are read into: the scene being built and, inside an item table
// (materials.NAME, [[species]], contact.pairs."a-b"), the item.
struct Reading {
  explicit Reading(Scene& scene) : s(scene) {}
  Scene& s;
  std::map<std::string, Material> materials = {{"steel", steel()}, {"aluminium", aluminium()}};
  // The law's parameters as given (models/law_parameters.hpp); absent ones take
  // their default once [inflow] is read (the inflow speed).
  std::array<std::optional<double>, kMaxLawParameters> law_parameters;
  std::optional<double> calibration_speed;  // default: the inflow speed
  Material material;
  Species species;
  std::map<std::string, int> species_by_name;  // pair names are looked up once per pair
  double number_fraction = 0;
  int pair_a = 0, pair_b = -1;  // pair_b < 0: "a-obstacle"
  Obstacle obstacle;
};

// What the keys of a table are written from: the resolved scene and, in an item table,
// the item.
struct Writing {
  const Scene& s;
  const Material* material = nullptr;
  std::size_t species = 0;
  int pair_a = 0, pair_b = -1;  // pair_b < 0: "a-obstacle"
};

using Read = void (*)(TableReader& r, Reading& st, const std::string& k);
using Write = void (*)(const Writing& w, toml::table& t, const std::string& k);

struct Key {
  const char* name;
  const char* type;  // the type column of docs/scene_keys.md; null: a table of item tables
  KeyDoc doc;        // the other columns of docs/scene_keys.md (granshock keys)
  Read read;
  Write write;
};

struct Table {
  // The TOML table; for item tables, as docs/scene_format.md writes it ("materials.NAME",
  // "[[species]]", "contact.pairs.\"a-b\"").
  const char* name;
  const Key* keys;
  std::size_t size;
  void (*after)(Reading& st);  // checks across the table's keys, once all are read; or null

  const Key* begin() const { return keys; }
  const Key* end() const { return keys + size; }
};

template <std::size_t N>
constexpr Table table(const char* name, const Key (&keys)[N], void (*after)(Reading&) = nullptr) {
  return {name, keys, N, after};
}

// Reads the keys of `t` in their order, then its checks across keys, then refuses the keys
// nobody asked for.
void read_keys(TableReader& r, Reading& st, const Table& t);
// read_keys on the table t.name of `top`.
void read_table(TableReader& top, Reading& st, const Table& t);
toml::table write_keys(const Writing& w, const Table& t);

// The material, or the index of the species, a key names; an unknown one is refused.
const Material& material_named(Reading& st, const std::string& key, const std::string& name);
int find_species(const Reading& st, const std::string& name);  // -1: none of that name
int species_index(const Reading& st, const std::string& key, const std::string& name);

// Adds a key that several owners (laws, shapes) may declare to a table's keys, once: the
// first owner to declare it places it, a later one must give it the same type.
void add_owned_key(std::vector<Key>& keys, const char* name, const char* type, KeyDoc doc,
                   Read read, Write write);

// The owners of a key, as a refusal names them: "hooke" or "linear".
template <class Kind>
std::string quoted_names(const std::vector<Kind>& owners) {
  std::vector<std::string> names;
  for (Kind k : owners) names.push_back(fmt::format("\"{}\"", choice_name(k)));
  return fmt::format("{}", fmt::join(names, " or "));
}

// ---- The sections (io/scene_schema_*.cpp) ----------------------------------------------
// scene_schema_particles.cpp
extern const Table kUnits, kScene, kMaterial, kSpecies;
// Materials defined in the scene join the built-in steel and aluminium (or replace them).
void read_materials(TableReader& top, Reading& st);
// The [[species]] tables, with the checks across them.
void read_species(TableReader& top, Reading& st);
// scene_schema_contact.cpp
extern const Table kPair, kContact, kNumerics;
// scene_schema_domain.cpp
extern const Table kDomain, kInflow, kObstacle;
// scene_schema_run.cpp
extern const Table kTime, kOutput;

}  // namespace granshock::scene_toml::schema_detail

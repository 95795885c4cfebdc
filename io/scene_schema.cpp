// The scene schema: one table of keys per TOML table of a scene file (docs/scene_format.md,
// "Keys"). Each key is declared here once, with its reader (type, default, limits, the
// message of a refusal) and its writer (the resolved scene). read_scene and write_scene
// walk the same tables; scene_keys() lists them for the test that docs/scene_format.md
// documents exactly these keys (tests/scene/test_scene_schema.cpp).
#include "io/scene_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "core/choice_names.hpp"
#include "io/scene_file.hpp"
#include "io/table_reader.hpp"
#include "kernels/models/law_parameters.hpp"
#include "kernels/models/obstacle_shapes.hpp"

namespace granshock {
namespace scene_toml {

namespace {

// More blocks than this only divide the production window into noise (and memory).
constexpr long kMaxBlocks = 10000;

// The most species a scene may have (docs/scene_format.md, "Limits"). Every pair has its
// own contact table, written in full into the resolved scene (about 160 KB of TOML at 64
// species, 2.4 MB at 256: past the 1 MiB a scene file may hold), kept as the force
// kernel's coefficient table (200 KB at 64, in cache) and collided twice for summary.json;
// the field sums grow with the species as well. The paper's mixture has two.
constexpr long kMaxSpecies = 64;

// Physical ranges of the scene's numbers (docs/scene_keys.md): values outside
// them passed every check and failed late, as -nan particle counts (units.d = 1e-320),
// a diameter of 1e-320 m, or a restitution of 1e-6 that ran the whole simulation before
// its effective restitution could not be measured.
struct Range {
  double lo, hi;
  const char* why;
};
// Particle sizes (and the unit d): micrometre powders to metre boulders.
constexpr Range kDiameter = {1e-6, 1.0, "from a micrometre powder to a metre boulder"};
constexpr Range kYoungsModulus = {1e3, 1e13, "from a hydrogel to past diamond's 1.2e12 Pa"};
constexpr Range kDensity = {1.0, 1e5, "from an aerogel to past osmium's 22590 kg/m3"};
// Below 0.01 the damped Hertz law's rebound creeps: a contact lasts 2.7 t_c at e = 0.01 and
// 25 t_c at e = 1e-6, and the integrator at the usual steps returns under half of e
// (docs/contact_model.md, "Restitution range").
constexpr Range kRestitution = {
    0.01, 1.0,
    "below 0.01 the damped contact law's rebound is not resolved (docs/contact_model.md)"};
constexpr Range kFriction = {0.0, 10.0, "Coulomb friction of real materials is below 2"};
// Speeds: the inflow, its fluctuation and the speeds contacts are calibrated at.
constexpr Range kSpeed = {1e-6, 1e4, "from a micrometre per second to hypervelocity"};
constexpr Range kSigma = {0.0, 1e4, "at most hypervelocity"};
constexpr Range kMach = {0.1, 1e4, "from a subsonic to a hypersonic gas"};
constexpr Range kSoftening = {1.0, 1e9, "every modulus divided by this stays at least 1e-9 of it"};
constexpr Range kNumberFraction = {1e-6, 1.0, "at least one particle in a million"};
constexpr double kMinAreaFraction = 1e-6;
// The domain's extent: positions are double, resolved to 2e-12 m at 10 km.
constexpr double kMaxDomainLength = 1e4;
constexpr Range kProgressInterval = {0.01, 1e9, "wall-clock seconds"};

// A number as docs/scene_keys.md writes it, the shorter of plain and exponent form (plain
// on a tie): 1e-6, 1e4, 0.5, 90 (not 1e-06, 10000).
std::string short_number(double value) {
  const std::string plain = fmt::format("{:g}", value);
  std::string text = fmt::format("{:e}", value);
  const std::size_t e = text.find('e');
  std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
  if (mantissa.find('.') != std::string::npos) {
    mantissa.erase(mantissa.find_last_not_of('0') + 1);
    if (mantissa.back() == '.') mantissa.pop_back();
  }
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  const std::string short_form =
      exponent.empty() ? mantissa : mantissa + "e" + (negative ? "-" : "") + exponent;
  return short_form.size() < plain.size() ? short_form : plain;
}

// The unit a key's type names: "N/m" of "number (N/m)"; none for a plain "number".
std::string unit_of_type(const std::string& type) {
  const std::size_t open = type.find('('), close = type.rfind(')');
  return open == std::string::npos || close < open ? "" : type.substr(open + 1, close - open - 1);
}

// A pair key's name for the obstacle ("a-obstacle"); no species may take it.
const char* const kObstacleName = "obstacle";

// A scene name names the run directory runs/<name>: it must be a plain file name.
bool is_safe_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.' || name[0] == '-') return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'))
      return false;
  return true;
}

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
  // The law's parameters as given (kernels/models/law_parameters.hpp); absent ones take
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
void read_keys(TableReader& r, Reading& st, const Table& t) {
  for (const Key& k : t) k.read(r, st, k.name);
  if (t.after) t.after(st);
  r.finish();
}

void read_table(TableReader& top, Reading& st, const Table& t) {
  TableReader r(top.table(t.name), t.name, st.s.d_m);
  read_keys(r, st, t);
}

toml::table write_keys(const Writing& w, const Table& t) {
  toml::table out;
  for (const Key& k : t) k.write(w, out, k.name);
  return out;
}

const Material& material_named(Reading& st, const std::string& key, const std::string& name) {
  const auto it = st.materials.find(name);
  if (it == st.materials.end()) {
    std::vector<std::string> names;
    for (const auto& [n, m] : st.materials) names.push_back(n);
    fail(key, '"' + name + '"',
         fmt::format("unknown material (defined: {})", fmt::join(names, ", ")));
  }
  return it->second;
}

int find_species(const Reading& st, const std::string& name) {
  const auto it = st.species_by_name.find(name);
  return it == st.species_by_name.end() ? -1 : it->second;
}

int species_index(const Reading& st, const std::string& key, const std::string& name) {
  const int a = find_species(st, name);
  if (a < 0) fail(key, '"' + name + '"', "unknown species");
  return a;
}

// ---- [units] -----------------------------------------------------------------------------

const Key kUnitsKeys[] = {
    {"d",
     "number (m)",
     {"m", "`[1e-6, 1]`", "`0.001`", "the length unit `d` of `\"N d\"`"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.d_m = r.number_within(k, kDiameter.lo, kDiameter.hi, 1e-3, kDiameter.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.d_m); }},
};
const Table kUnits = table("units", kUnitsKeys);

// ---- [scene] -----------------------------------------------------------------------------

const Key kSceneKeys[] = {
    {"name",
     "string",
     {"", "1-64 of `A-Z a-z 0-9 . _ -`, not starting with `.` or `-`", "`\"unnamed\"`",
      "names the run directory `runs/<name>`"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.name = r.string(k, "unnamed");
       if (!is_safe_name(st.s.name))
         fail(r.key(k), '"' + st.s.name + '"',
              "must be 1 to 64 characters of A-Z a-z 0-9 . _ -, not starting with '.' or '-' "
              "(it names the run directory runs/<name>)");
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.name); }},
    {"dim",
     "integer",
     {"", "2 only", "`2`", "quasi-2-D (centres in the x-y plane)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const long dim = r.integer_at_least(k, 2, 2);
       if (dim != 2)
         fail(r.key(k), std::to_string(dim), "only quasi-2-D scenes (dim = 2) are supported");
       st.s.setup.dim = 2;
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.setup.dim); }},
    {"seed",
     "integer",
     {"", "`>= 0`", "`1`", "seed of the counter-based RNG (inflow positions, velocities)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.seed = std::uint64_t(r.integer_at_least(k, 0, 1));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, std::int64_t(w.s.run.seed));
     }},
};
const Table kScene = table("scene", kSceneKeys);

// ---- [materials.NAME] --------------------------------------------------------------------

const Key kMaterialKeys[] = {
    {"youngs_modulus",
     "number (Pa)",
     {"Pa", "`[1e3, 1e13]`", "required",
      "defines material NAME (`steel` and `aluminium` are built in, the paper's values; a "
      "`[materials.steel]` table replaces the built-in one)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.material.youngs_modulus_pa =
           r.number_within(k, kYoungsModulus.lo, kYoungsModulus.hi, {}, kYoungsModulus.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.material->youngs_modulus_pa);
     }},
    {"poisson_ratio",
     "number",
     {"", "`(-1, 0.5)`", "required", "nu: each body adds (1 - nu^2) / E to the Hertz law's 1 / E*"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.material.poisson_ratio = r.number_in(k, -1.0, 0.5, true, true);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.material->poisson_ratio);
     }},
    {"density",
     "number (kg/m3)",
     {"kg/m3", "`[1, 1e5]`", "required", "rho: a sphere of diameter d weighs rho pi d^3 / 6"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.material.density_kg_m3 = r.number_within(k, kDensity.lo, kDensity.hi, {}, kDensity.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.material->density_kg_m3);
     }},
};
const Table kMaterial = table("materials.NAME", kMaterialKeys);

// A species' or material's name goes into table headers, CSV headers, file names' text and
// messages: 1 to 64 characters, none of them a control character (a newline in a name
// ended as an internal error in the resolved scene's TOML).
// The name as a message shows it: quoted, control characters escaped ("st\\neel").
std::string show_name(const std::string& name) {
  std::string shown = "\"";
  for (char c : name) {
    if (c == '\n')
      shown += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      shown += fmt::format("\\x{:02x}", int(static_cast<unsigned char>(c)));
    else
      shown += c;
  }
  return shown + '"';
}

void check_name(const std::string& path, const std::string& name) {
  const bool control = std::any_of(name.begin(), name.end(), [](char c) {
    return (static_cast<unsigned char>(c) < 0x20) || c == 0x7f;
  });
  if (control || name.empty() || name.size() > 64)
    fail(path, show_name(name),
         "a name is 1 to 64 characters, without control characters (newline, tab, ...)");
}

// Materials defined in the scene join the built-in steel and aluminium (or replace them).
void read_materials(TableReader& top, Reading& st) {
  const toml::table* mt = top.table("materials");
  if (!mt) return;
  for (const auto& [key, value] : *mt) {
    const std::string name(key.str());
    check_name("materials." + show_name(name), name);
    if (!value.is_table()) fail("materials." + name, show(value), "must be a table");
    TableReader r(value.as_table(), "materials." + name, st.s.d_m);
    st.material = Material{};
    read_keys(r, st, kMaterial);
    st.material.name = name;
    st.materials[name] = st.material;
  }
}

// ---- [[species]] -------------------------------------------------------------------------

const Key kSpeciesKeys[] = {
    {"name",
     "string",
     {"",
      "1-64 characters, no control characters; unique; not `obstacle`; a dash only where every "
      "pair key still names one pair (`a`, `b-c`, `a-b`, `c` would make `a-b-c` name two)",
      "required", "one table per species, at most 64 (scene_format.md, \"Limits\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.species.name = r.string(k);
       check_name(r.key(k), st.species.name);
       if (find_species(st, st.species.name) >= 0)
         fail(r.key(k), '"' + st.species.name + '"', "species names must be unique");
       if (st.species.name == kObstacleName || st.species.name.empty())
         fail(r.key(k), '"' + st.species.name + '"',
              "a species may not be named \"obstacle\" (contact.pairs.\"a-obstacle\" names "
              "the obstacle) nor \"\"");
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.species[w.species].name);
     }},
    {"material",
     "string",
     {"", "a material (built in or `materials.NAME`)", "required",
      "the species' modulus, Poisson ratio and density"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.species.material = material_named(st, r.key(k), r.string(k));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.species[w.species].material.name);
     }},
    {"diameter",
     "length",
     {"m, `\"N d\"`", "`[1e-6, 1]` m", "required", "spheres: m = rho pi d^3 / 6"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.species.diameter_m = r.length_within(k, kDiameter.lo, kDiameter.hi, {}, kDiameter.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.species[w.species].diameter_m);
     }},
    {"number_fraction",
     "number",
     {"", "`[1e-6, 1]`; the species' fractions sum to 1 (within 1e-9)", "required",
      "of the inflow"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.number_fraction =
           r.number_within(k, kNumberFraction.lo, kNumberFraction.hi, {}, kNumberFraction.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.number_fraction[w.species]);
     }},
};
const Table kSpecies = table("[[species]]", kSpeciesKeys);

// Every pair key ("a-b" in either order, "a-obstacle") must name one pair: a dash inside a
// species name could make "a-b-c" both a with b-c and a-b with c, and a species named
// "obstacle" would share its keys with the obstacle, so that one key set two pairs while
// the resolved scene showed one. Checked over all pair keys once the species are known.
void refuse_ambiguous_pair_keys(const Reading& st) {
  const std::vector<Species>& species = st.s.setup.species;
  const int n = int(species.size());
  std::map<std::string, std::pair<int, int>> pair_of_key;  // b = -1: the obstacle
  const auto claim = [&](const std::string& key, int a, int b) {
    const std::pair<int, int> pair(b < 0 ? a : std::min(a, b), b < 0 ? b : std::max(a, b));
    const auto [it, fresh] = pair_of_key.emplace(key, pair);
    if (fresh || it->second == pair) return;
    const auto name = [&](int k) { return k < 0 ? std::string(kObstacleName) : species[k].name; };
    const int later = std::max({a, b, it->second.first, it->second.second});
    fail(fmt::format("species.{}.name", later), '"' + species[later].name + '"',
         fmt::format("the pair key \"{}\" would name both {} with {} and {} with {}; choose "
                     "species names that no dash can split two ways",
                     key, name(it->second.first), name(it->second.second), name(pair.first),
                     name(pair.second)));
  };
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) claim(species[a].name + "-" + species[b].name, a, b);
    claim(species[a].name + "-" + kObstacleName, a, -1);
  }
}

void read_species(TableReader& top, Reading& st) {
  const toml::node* sp = top.node("species");
  if (!sp || !sp->is_array_of_tables() || sp->as_array()->empty())
    fail("species", sp ? show(*sp) : "(missing)", "needs one or more [[species]] tables");
  if (sp->as_array()->size() > std::size_t(kMaxSpecies))
    fail("species", fmt::format("{} [[species]] tables", sp->as_array()->size()),
         fmt::format("at most {} species (docs/scene_format.md, \"Limits\": every pair of "
                     "species has its own contact table)",
                     kMaxSpecies));
  double fraction_sum = 0;
  int index = 0;
  for (const auto& item : *sp->as_array()) {
    TableReader r(item.as_table(), fmt::format("species.{}", index++), st.s.d_m);
    st.species = Species{};
    for (const Key& k : kSpecies) k.read(r, st, k.name);
    fraction_sum += st.number_fraction;
    st.s.inflow.number_fraction.push_back(st.number_fraction);
    st.species_by_name[st.species.name] = int(st.s.setup.species.size());
    st.s.setup.species.push_back(st.species);
    r.finish();
  }
  if (std::abs(fraction_sum - 1.0) > 1e-9)
    fail("species.*.number_fraction", fmt::format("sum {}", fraction_sum),
         "the number fractions must add up to 1");
  refuse_ambiguous_pair_keys(st);
}

// ---- [contact.pairs."a-b"] ---------------------------------------------------------------

const Key kPairKeys[] = {
    {"restitution",
     "number",
     {"", "`[0.01, 1]`", "`contact.restitution`",
      "per pair of species a, b; `\"a-obstacle\"` for the obstacle"},
     [](TableReader& r, Reading& st, const std::string& k) {
       ContactSettings& c = st.s.setup.contacts;
       const int a = st.pair_a, b = st.pair_b;
       if (b < 0) {
         c.obstacle_restitution[a] = r.number_within(k, kRestitution.lo, kRestitution.hi,
                                                     c.obstacle_restitution[a], kRestitution.why);
       } else {
         const double e = r.number_within(k, kRestitution.lo, kRestitution.hi, c.restitution[a][b],
                                          kRestitution.why);
         c.restitution[a][b] = c.restitution[b][a] = e;
       }
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       const ContactSettings& c = w.s.setup.contacts;
       t.insert(
           k, w.pair_b < 0 ? c.obstacle_restitution[w.pair_a] : c.restitution[w.pair_a][w.pair_b]);
     }},
    {"friction",
     "number",
     {"", "`[0, 10]`", "`contact.friction`", "per pair, as restitution"},
     [](TableReader& r, Reading& st, const std::string& k) {
       ContactSettings& c = st.s.setup.contacts;
       const int a = st.pair_a, b = st.pair_b;
       if (b < 0) {
         c.obstacle_friction[a] =
             r.number_within(k, kFriction.lo, kFriction.hi, c.obstacle_friction[a], kFriction.why);
       } else {
         const double mu =
             r.number_within(k, kFriction.lo, kFriction.hi, c.friction[a][b], kFriction.why);
         c.friction[a][b] = c.friction[b][a] = mu;
       }
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       const ContactSettings& c = w.s.setup.contacts;
       t.insert(k, w.pair_b < 0 ? c.obstacle_friction[w.pair_a] : c.friction[w.pair_a][w.pair_b]);
     }},
};
const Table kPair = table("contact.pairs.\"a-b\"", kPairKeys);

// The species a, b of a pair named "a-b" (b = -1 for "a-obstacle"). Species names may
// hold '-' (the resolved scene names every pair), so each dash is tried in turn; when
// none splits the name into known names, the part the first dash leaves unknown is named.
std::pair<int, int> pair_named(const Reading& st, const std::string& path,
                               const std::string& name) {
  for (auto dash = name.find('-'); dash != std::string::npos; dash = name.find('-', dash + 1)) {
    const std::string other = name.substr(dash + 1);
    const int a = find_species(st, name.substr(0, dash));
    const int b = other == "obstacle" ? -1 : find_species(st, other);
    if (a >= 0 && (b >= 0 || other == "obstacle")) return {a, b};
  }
  const auto dash = name.find('-');
  const int a = species_index(st, path, name.substr(0, dash));
  const std::string other = name.substr(dash + 1);
  return {a, other == "obstacle" ? -1 : species_index(st, path, other)};
}

// contact.pairs: one table per pair of species "a-b" and per species against the obstacle
// "a-obstacle", each overriding contact.restitution and contact.friction.
void read_pairs(TableReader& r, Reading& st, const std::string& k) {
  const toml::table* pairs = r.table(k);
  if (!pairs) return;
  for (const auto& [key, value] : *pairs) {
    const std::string name(key.str()), path = r.key(k) + "." + name;
    const auto dash = name.find('-');
    if (dash == std::string::npos || !value.is_table())
      fail(path, show(value), "must be a table named \"a-b\" or \"a-obstacle\" for species a, b");
    std::tie(st.pair_a, st.pair_b) = pair_named(st, path, name);
    TableReader pr(value.as_table(), path, st.s.d_m);
    read_keys(pr, st, kPair);
  }
}

void write_pairs(const Writing& w, toml::table& t, const std::string& k) {
  const std::vector<Species>& species = w.s.setup.species;
  toml::table pairs;
  Writing p = w;
  for (std::size_t a = 0; a < species.size(); ++a) {
    p.pair_a = int(a);
    for (std::size_t b = a; b < species.size(); ++b) {
      p.pair_b = int(b);
      pairs.insert(species[a].name + "-" + species[b].name, write_keys(p, kPair));
    }
    p.pair_b = -1;
    pairs.insert(species[a].name + "-obstacle", write_keys(p, kPair));
  }
  t.insert(k, pairs);
}

// ---- [contact] ---------------------------------------------------------------------------

const Key kContactKeys[] = {
    {"restitution",
     "number",
     {"", "`[0.01, 1]` (contact_model.md, \"Restitution range\")", "required",
      "every pair and the obstacle"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double e = r.number_within(k, kRestitution.lo, kRestitution.hi, {}, kRestitution.why);
       st.s.setup.contacts = ContactSettings::uniform(int(st.s.setup.species.size()), e, 0.0);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.contacts.restitution[0][0]);
     }},
    {"friction",
     "number",
     {"", "`[0, 10]`", "`0`", "Coulomb mu; 0 compiles no tangential force"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double mu = r.number_within(k, kFriction.lo, kFriction.hi, 0.0, kFriction.why);
       ContactSettings& c = st.s.setup.contacts;
       for (auto& row : c.friction) row.assign(row.size(), mu);
       c.obstacle_friction.assign(c.obstacle_friction.size(), mu);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.contacts.friction[0][0]);
     }},
    {"restitution_mode",
     "string",
     {"", "continuous, discrete", "`\"continuous\"`",
      "`discrete`: every pair's damping is calibrated at start-up so that the solver at this dt "
      "returns e, averaged over the phase of the first contact step (contact_model.md, "
      "\"Restitution at the chosen time step\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.contacts.restitution_mode = read_choice(r, k, RestitutionMode::continuous);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, to_string(w.s.setup.contacts.restitution_mode));
     }},
    // Its default, the inflow speed, is known once [inflow] is read (read_scene).
    {"calibration_speed",
     "number (m/s)",
     {"m/s", "`[1e-6, 1e4]`", "`inflow.velocity`",
      "`discrete` only: the impact speed of the calibration"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (r.has(k))
         st.calibration_speed = r.number_within(k, kSpeed.lo, kSpeed.hi, {}, kSpeed.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.contacts.calibration_speed_m_per_s);
     }},
    {"softening",
     "number",
     {"", "`[1, 1e9]`", "`1`",
      "every Young's modulus (particles and obstacle) divided by this for the contacts: t_c and "
      "the peak overlap grow as softening^(2/5) (Hertz), so dt may grow with it; restitution, "
      "masses and sizes are kept (contact_model.md, \"Softening\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.contacts.softening =
           r.number_within(k, kSoftening.lo, kSoftening.hi, 1.0, kSoftening.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.contacts.softening);
     }},
    {"model",
     "string",
     {"", "hertz, hooke, linear", "`\"hertz\"`",
      "the contact law: `hertz` (contact_model.md), `hooke`, LIGGGHTS' linear spring-dashpot with "
      "a constant kn from a characteristic velocity (`kernels/models/hooke.hpp`), or `linear`, the "
      "same spring-dashpot with the kn the scene gives (`kernels/models/linear.hpp`); each law "
      "takes only its own parameter keys"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.contacts.model = read_choice(r, k, ContactModelKind::hertz);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, to_string(w.s.setup.contacts.model));
     }},
    {"limit_force",
     "bool",
     {"", "", "`false`", "clamp Fn >= 0 (contact_model.md, \"limit_force\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.contacts.options.limit_force = r.boolean(k, false);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.contacts.options.limit_force);
     }},
};

// Adds a key that several owners (laws, shapes) may declare to a table's keys, once: the
// first owner to declare it places it, a later one must give it the same type.
void add_owned_key(std::vector<Key>& keys, const char* name, const char* type, KeyDoc doc,
                   Read read, Write write) {
  const auto known = std::find_if(keys.begin(), keys.end(),
                                  [&](const Key& k) { return k.name == std::string(name); });
  if (known == keys.end()) {
    keys.push_back({name, type, std::move(doc), read, write});
    return;
  }
  if (std::string(known->type) != type)
    throw std::logic_error(std::string("two owners give the scene key ") + name +
                           " different types");
}

// The owners of a key, as a refusal names them: "hooke" or "linear".
template <class Kind>
std::string quoted_names(const std::vector<Kind>& owners) {
  std::vector<std::string> names;
  for (Kind k : owners) names.push_back(fmt::format("\"{}\"", choice_name(k)));
  return fmt::format("{}", fmt::join(names, " or "));
}

// The parameter keys of the contact laws, each declared once in its law's parameter
// header (kernels/models/law_parameters.hpp) and found there by name: read when the
// scene's contact.model owns it, refused when given for another law, written back for its
// own law only (as the obstacle's size keys are).
void read_law_key(TableReader& r, Reading& st, const std::string& k) {
  const ContactModelKind model = st.s.setup.contacts.model;
  const std::optional<std::size_t> own = law_key_index(model, k);
  if (!own) {
    if (const toml::node* n = r.node(k))
      fail(r.key(k), show(*n),
           fmt::format("is a key of contact.model = {}, and the model is \"{}\"",
                       quoted_names(laws_with_key(k)), choice_name(model)));
    return;
  }
  with_law_parameters(model, [&](auto parameters) {
    const LawKey& key = parameters.keys[*own];
    if (r.has(k) || key.fallback == LawKey::Default::required)
      st.law_parameters[*own] = r.number_within(k, key.lo, key.hi, {}, key.why);
  });
}

void write_law_key(const Writing& w, toml::table& t, const std::string& k) {
  if (const std::optional<std::size_t> own = law_key_index(w.s.setup.contacts.model, k))
    t.insert(k, w.s.setup.contacts.options.law_parameters[*own]);
}

// A law key's row of docs/scene_keys.md, from its law's declaration: owned by every law
// that declares the name ("`hooke`'s"), the range and meaning of the first.
KeyDoc law_key_doc(const LawKey& key) {
  std::vector<std::string> owners;
  for (ContactModelKind law : laws_with_key(key.name))
    owners.push_back(fmt::format("`{}`", choice_name(law)));
  const std::string laws = fmt::format("{}", fmt::join(owners, " or "));
  return {unit_of_type(key.type),
          fmt::format("`[{}, {}]`", short_number(key.lo), short_number(key.hi)),
          key.fallback == LawKey::Default::required ? "required for " + laws
                                                    : std::string("`inflow.velocity`"),
          fmt::format("{}'s: {}; refused for another law", laws, key.meaning)};
}

// [contact]'s keys: the table above, then every law's parameter keys (each name once, in
// the order of LawParameterSets; after contact.model, which says whose they are), then the
// pair tables.
std::vector<Key> contact_keys() {
  std::vector<Key> keys(std::begin(kContactKeys), std::end(kContactKeys));
  for_each_law_parameters([&](auto parameters) {
    for (const LawKey& key : parameters.keys)
      add_owned_key(keys, key.name, key.type, law_key_doc(key), read_law_key, write_law_key);
  });
  keys.push_back({"pairs", nullptr, {}, read_pairs, write_pairs});
  return keys;
}
const std::vector<Key> kContactKeyList = contact_keys();
const Table kContact = {"contact", kContactKeyList.data(), kContactKeyList.size(), nullptr};

// ---- [numerics] --------------------------------------------------------------------------

const Key kNumericsKeys[] = {
    {"precision",
     "string",
     {"", "double, single", "`\"double\"`",
      "arithmetic of velocities, forces, spins, springs and the contact law; positions are double "
      "in both, and separations are formed in double before rounding, so single is as accurate at "
      "the far edge of a large box as at the origin (design.md, \"Particles\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.precision = read_choice(r, k, Precision::double_precision);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, choice_name(w.s.setup.precision));
     }},
    {"skin",
     "length",
     {"m, `\"N d\"`", "`> 0`", "`0.3 d_max`",
      "Verlet skin; lists rebuilt after skin/2 of motion; with `adaptive_skin` the largest skin "
      "(the cells are sized for it)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.skin_m = r.length(k, 0.3 * st.s.setup.max_diameter());
       if (!(st.s.setup.skin_m > 0))
         fail(r.key(k), fmt::format("{} m", st.s.setup.skin_m), "must be > 0");
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.setup.skin_m); }},
    {"adaptive_skin",
     "bool",
     {"", "", "`false`",
      "re-choose the skin at each list build that motion forced, between 0.05 d_max and `skin`, by "
      "a cost model of counted list lengths and rebuild intervals (design.md, \"Adaptive skin\"); "
      "dense scenes run faster (+30 % in the gas at phi = 0.5, benchmarks.md), trajectories differ "
      "from a fixed skin's at round-off"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.adaptive_skin = r.boolean(k, false);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.adaptive_skin);
     }},
    {"mass_definition",
     "string",
     {"", "mixture_mean, paper_sum", "`\"mixture_mean\"`",
      "m in the sound speed (fields.md, \"The mass m in the sound speed, and the default\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.mass_definition = read_choice(r, k, MassDefinition::mixture_mean);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, to_string(w.s.mass_definition));
     }},
    {"bin_size",
     "length",
     {"m, `\"N d\"`", "`> 0`, at least d_max; enough bins (scene_format.md, \"Field sampling\")",
      "`\"3 d\"`",
      "field bins: the grid's bins are adjusted to within half a bin over the length they tile, so "
      "that they tile the width with a column centred on the obstacle's axis and put a row edge on "
      "its upstream face (fields.md, section 1)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.bin_size_m = r.positive_length(k, 3 * st.s.d_m);
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.bin_size_m); }},
    {"field_scatter",
     "string",
     {"", "auto, atomic, scatter_view, rows", "`\"auto\"`",
      "how samples are scattered into bins: auto takes rows on host backends (bitwise reproducible "
      "sums) and atomic on GPUs (fields.md, \"Cost of sampling: row owners, atomics, "
      "ScatterView\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.field_scatter = read_choice(r, k, ScatterStrategy::automatic);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, choice_name(w.s.field_scatter));
     }},
};
const Table kNumerics = table("numerics", kNumericsKeys);

// ---- [domain] ----------------------------------------------------------------------------

const Key kDomainKeys[] = {
    {"width",
     "length",
     {"m, `\"N d\"`", "`> 0`, at least 3 (d_max + `numerics.skin`), at most 1e4 m", "required",
      "crosswise x, periodic"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.box.hi[0] = r.positive_length(k);
       if (st.s.setup.box.hi[0] > kMaxDomainLength)
         fail(r.key(k), fmt::format("{} m", st.s.setup.box.hi[0]),
              fmt::format("must be at most {:g} m", kMaxDomainLength));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.box.hi[0]);
     }},
    {"length",
     "length",
     {"m, `\"N d\"`", "`> 0`, longer than `inflow.strip`, at most 1e4 m", "required",
      "streamwise y: inflow at 0, outflow at length"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.box.hi[1] = r.positive_length(k);
       if (st.s.setup.box.hi[1] > kMaxDomainLength)
         fail(r.key(k), fmt::format("{} m", st.s.setup.box.hi[1]),
              fmt::format("must be at most {:g} m", kMaxDomainLength));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.box.hi[1]);
     }},
};
// Periodic across (x), open along the flow (y), one diameter thick (z).
void after_domain(Reading& st) {
  SolverSetup& setup = st.s.setup;
  const double width = setup.box.hi[0], range = setup.max_diameter() + setup.skin_m;
  if (width < 3 * range)
    fail("domain.width", fmt::format("{} m", width),
         fmt::format("must be at least 3 interaction ranges, each the largest diameter plus "
                     "numerics.skin ({} m)",
                     3 * range));
  setup.box.lo = {0, 0, 0};
  setup.box.hi[2] = setup.max_diameter();
  setup.box.periodic = {true, false, false};
  setup.delete_outside = true;
}
const Table kDomain = table("domain", kDomainKeys, after_domain);

// ---- [inflow] ----------------------------------------------------------------------------

const Key kInflowKeys[] = {
    {"area_fraction",
     "number",
     {"", "`[1e-6, 0.4]`", "required",
      "phi_inf; the limit is what the inflow can insert (scene_format.md, \"The inflow\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double phi = st.s.inflow.area_fraction = r.positive(k);
       if (phi < kMinAreaFraction)
         fail(r.key(k), fmt::format("{}", phi),
              fmt::format("must be at least {}: a gas that dilute leaves the field bins empty",
                          kMinAreaFraction));
       if (phi > kMaxInflowAreaFraction)
         fail(r.key(k), fmt::format("{}", phi),
              fmt::format("must be in (0, {}]: random insertion in the strip reaches about 0.42 "
                          "(measured; random sequential adsorption of discs jams at 0.547, "
                          "Hinrichsen, Feder & Jossang 1986), so more cannot be met "
                          "(docs/scene_format.md)",
                          kMaxInflowAreaFraction));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.area_fraction);
     }},
    {"velocity",
     "number (m/s)",
     {"m/s", "`[1e-6, 1e4]`", "required", "U along +y"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.inflow.speed_m_per_s = r.number_within(k, kSpeed.lo, kSpeed.hi, {}, kSpeed.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.speed_m_per_s);
     }},
    // Written back as the sigma used, also when the scene gave a Mach number.
    {"sigma",
     "number (m/s)",
     {"m/s", "`[0, 1e4]`", "one of `inflow.sigma`, `inflow.mach`",
      "Gaussian fluctuation per component"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (r.has(k) == r.has("mach"))
         fail("inflow.sigma / inflow.mach", "(both or neither)",
              "give exactly one: sigma (m/s) or mach");
       if (r.has(k))
         st.s.inflow.sigma_m_per_s = r.number_within(k, kSigma.lo, kSigma.hi, {}, kSigma.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.inflow.sigma); }},
    // Resolved into inflow.sigma (resolve_inflow), which carries it into the resolved scene.
    {"mach",
     "number",
     {"", "`[0.1, 1e4]`", "one of `inflow.sigma`, `inflow.mach`",
      "target Ma_inf; sigma follows from it (scene_format.md, \"The inflow\"); the resolved scene "
      "holds the sigma"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (r.has(k))
         st.s.inflow.target_mach = r.number_within(k, kMach.lo, kMach.hi, {}, kMach.why);
     },
     [](const Writing&, toml::table&, const std::string&) {}},
    // Where the Mach number is meant (docs/fields.md, "Three upstream Mach numbers"). Like
    // mach, it says how sigma is found; the resolved scene carries the sigma found.
    {"mach_at",
     "string",
     {"", "inserted, inlet_bins", "`\"inserted\"`",
      "where mach is meant (`inlet_bins` needs `inflow.mach`): the inserted state, or measured "
      "over the two inlet bin rows as the paper does, sigma calibrated before the run (fields.md, "
      "\"Three upstream Mach numbers\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.inflow.mach_at = read_choice(r, k, MachReference::inserted);
       if (st.s.inflow.mach_at == MachReference::inlet_bins && !st.s.inflow.target_mach)
         fail(r.key(k), fmt::format("\"{}\"", choice_name(MachReference::inlet_bins)),
              "needs inflow.mach, the Mach number to calibrate sigma for");
     },
     [](const Writing&, toml::table&, const std::string&) {}},
    {"strip",
     "length",
     {"m, `\"N d\"`", "at least d_max, shorter than `domain.length`", "`\"2 d\"`",
      "insertion strip y in [0, strip]"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double strip = st.s.inflow.strip_m = r.length(k, 2 * st.s.d_m);
       if (strip < st.s.setup.max_diameter() || strip >= st.s.setup.box.hi[1])
         fail(r.key(k), fmt::format("{} m", strip),
              fmt::format("must be at least one diameter and shorter than domain.length ({} m)",
                          st.s.setup.box.hi[1]));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.strip_m);
     }},
};
const Table kInflow = table("inflow", kInflowKeys);

// ---- [obstacle] --------------------------------------------------------------------------

// The size keys of the shapes (docs/scene_format.md, [obstacle]), each declared once in its
// shape's header (`keys`, kernels/models/shape_key.hpp) and found here by name: a key is
// read into Obstacle::size when the obstacle has a shape that owns it, refused when it is
// given for another shape, and written back for its own shape only.
void read_shape_key(TableReader& r, Reading& st, const std::string& k) {
  const ObstacleShape shape = st.obstacle.shape;
  const std::optional<std::size_t> own = shape_key_index(shape, k);
  if (!own) {
    if (const toml::node* n = r.node(k))
      fail(r.key(k), show(*n),
           fmt::format("is a key of obstacle.shape = {}, and the shape is \"{}\"",
                       quoted_names(shapes_with_key(k)), choice_name(shape)));
    return;
  }
  const ShapeKey key = with_obstacle_shape(shape, [&](auto s) { return s.keys[*own]; });
  const std::optional<double> fallback =
      key.required() ? std::nullopt : std::optional<double>(key.fallback);
  double value = 0;
  if (key.kind == ShapeKey::Kind::angle) {
    value = r.number_in(k, key.lo, key.hi, !key.lo_closed, true, fallback);
  } else {
    value = r.positive_length(k, fallback);
    if (value < st.s.setup.max_diameter())
      fail(r.key(k), fmt::format("{} m", value),
           fmt::format("must be at least the largest particle diameter ({} m): the contact "
                       "law treats the {} as a wall",
                       st.s.setup.max_diameter(), choice_name(shape)));
  }
  st.obstacle.size[*own] = value;
}

void write_shape_key(const Writing& w, toml::table& t, const std::string& k) {
  const Obstacle& o = *w.s.setup.obstacle;
  if (const std::optional<std::size_t> own = shape_key_index(o.shape, k)) t.insert(k, o.size[*own]);
}

// A shape key's row of docs/scene_keys.md, from its shape's declaration (every shape that
// declares the name owns it; the range, default and meaning are the first's).
KeyDoc shape_key_doc(const ShapeKey& key) {
  std::vector<std::string> owners;
  for (ObstacleShape shape : shapes_with_key(key.name))
    owners.push_back(fmt::format("a {}", choice_name(shape)));
  const std::string shapes = fmt::format("{}", fmt::join(owners, " or "));
  const bool length = key.kind == ShapeKey::Kind::length;
  return {
      length ? "m, `\"N d\"`" : "degrees",
      length ? std::string("at least d_max (the contact law treats the obstacle as a wall)")
             : fmt::format("`{}{}, {})`", key.lo_closed ? "[" : "(", short_number(key.lo),
                           short_number(key.hi)),
      key.required() ? "required for " + shapes : fmt::format("`{}`", short_number(key.fallback)),
      key.required() ? key.meaning : fmt::format("{} only: {}", shapes, key.meaning)};
}

// [obstacle]'s keys: the shape, every shape's size keys (each name once, in the order of
// ObstacleShapes), the material and the centre.
std::vector<Key> obstacle_keys() {
  std::vector<Key> keys = {
      {"shape",
       "string",
       {"", "cylinder, wedge, plate, square", "`\"cylinder\"`",
        "a fixed prism along z: its cross-section (scene_format.md, \"Obstacle shapes\"); a "
        "`[obstacle]` table makes the obstacle (no table: no obstacle), and each shape takes only "
        "its own size keys"},
       [](TableReader& r, Reading& st, const std::string& k) {
         st.obstacle.shape = read_choice(r, k, ObstacleShape::cylinder);
       },
       [](const Writing& w, toml::table& t, const std::string& k) {
         t.insert(k, choice_name(w.s.setup.obstacle->shape));
       }},
  };
  for_each_obstacle_shape([&](auto s) {
    for (const ShapeKey& key : s.keys)
      add_owned_key(keys, key.name, key.type(), shape_key_doc(key), read_shape_key,
                    write_shape_key);
  });
  keys.push_back({"material",
                  "string",
                  {"", "a material", "`\"aluminium\"`",
                   "the obstacle's modulus and Poisson ratio in its contacts (it does not move)"},
                  [](TableReader& r, Reading& st, const std::string& k) {
                    st.obstacle.material = material_named(st, r.key(k), r.string(k, "aluminium"));
                  },
                  [](const Writing& w, toml::table& t, const std::string& k) {
                    t.insert(k, w.s.setup.obstacle->material.name);
                  }});
  keys.push_back({"centre",
                  "[length, length]",
                  {"m, `\"N d\"`",
                   "the shape inside the domain, its upstream end at least d_max past "
                   "`inflow.strip`, and a gap of at least 3 d_max beside it across the channel",
                   "`[domain.width / 2, domain.length / 2]`",
                   "the middle of the shape's extent along x and y (a cylinder's axis; half-way "
                   "from a wedge's tip to its base)"},
                  [](TableReader& r, Reading& st, const std::string& k) {
                    const Box& box = st.s.setup.box;
                    st.obstacle.centre = {0.5 * box.hi[0], 0.5 * box.hi[1], 0};
                    if (const toml::node* n = r.node(k)) {
                      const toml::array* a = n->as_array();
                      if (!a || a->size() != 2)
                        fail(r.key(k), show(*n), "must be [x, y] (two lengths)");
                      st.obstacle.centre[0] = r.length_of(*a->get(0), r.key(k) + "[0]");
                      st.obstacle.centre[1] = r.length_of(*a->get(1), r.key(k) + "[1]");
                    }
                  },
                  [](const Writing& w, toml::table& t, const std::string& k) {
                    const auto& c = w.s.setup.obstacle->centre;
                    t.insert(k, toml::array{c[0], c[1]});
                  }});
  return keys;
}
const std::vector<Key> kObstacleKeys = obstacle_keys();

// The least gap an obstacle leaves across the periodic channel, in particle diameters.
constexpr double kMinObstacleGapDiameters = 3;

// The shape's size keys with their values, as a refusal names them.
std::string obstacle_sizes(const Obstacle& c) {
  return with_obstacle_shape(c, [&](auto s) {
    std::vector<std::string> sizes;
    for (std::size_t i = 0; i < std::size(s.keys); ++i)
      sizes.push_back(fmt::format("{} {} {}", s.keys[i].name, c.size[i],
                                  s.keys[i].kind == ShapeKey::Kind::angle ? "deg" : "m"));
    return fmt::format("{}", fmt::join(sizes, ", "));
  });
}

// The keys that set the shape's width across the flow (the D of delta/D): those of its
// size keys whose change moves the width (a plate's width, not its thickness).
std::string frontal_width_keys(const Obstacle& c) {
  return with_obstacle_shape(c, [&](auto s) {
    std::vector<std::string> keys;
    for (std::size_t k = 0; k < std::size(s.keys); ++k) {
      Obstacle changed = c;
      changed.size[k] = c.size[k] == 0 ? 1.0 : 1.01 * c.size[k];
      if (obstacle_frontal_width(changed) != obstacle_frontal_width(c))
        keys.push_back(std::string("obstacle.") + s.keys[k].name);
    }
    return fmt::format("{}", fmt::join(keys, "' and '"));
  });
}

void after_obstacle(Reading& st) {
  const Obstacle& c = st.obstacle;
  const double across = 0.5 * obstacle_frontal_width(c), width = st.s.setup.box.hi[0];
  const double along = 0.5 * obstacle_streamwise_length(c), length = st.s.setup.box.hi[1];
  if (c.centre[0] - across < 0 || c.centre[0] + across > width ||
      c.centre[1] - along < st.s.inflow.strip_m + st.s.setup.max_diameter() ||
      c.centre[1] + along > length)
    fail("obstacle",
         fmt::format("centre ({}, {}) m, {} ({} m across and {} m along the flow)", c.centre[0],
                     c.centre[1], obstacle_sizes(c), 2 * across, 2 * along),
         fmt::format("the {} must lie inside the domain, downstream of the insertion strip",
                     choice_name(c.shape)));
  // The periodic channel beside it: an obstacle as wide as the domain closes it, and the
  // flow it is there to divert piles up in front of it instead.
  const double gap = width - 2 * across, d = st.s.setup.max_diameter();
  if (gap < kMinObstacleGapDiameters * d)
    fail(
        frontal_width_keys(c),
        fmt::format("{} m across the flow, in a channel of domain.width = {} m", 2 * across, width),
        fmt::format("the {} leaves a gap of {:.3g} particle diameters beside it; it must leave "
                    "at least {:g} for the flow to pass: make it narrower or the domain wider",
                    choice_name(c.shape), gap / d, kMinObstacleGapDiameters));
  st.s.setup.obstacle = c;
}
const Table kObstacle = {"obstacle", kObstacleKeys.data(), kObstacleKeys.size(), after_obstacle};

// ---- [time] ------------------------------------------------------------------------------

const Key kTimeKeys[] = {
    {"dt",
     "number (s)",
     {"s",
      "`> 0`; at most the stable limit (unless `--force`); `time.duration` / dt from 1 to 1e12 "
      "steps",
      "required", "the time step (scene_format.md, \"The time-step guard for scenes\")"},
     [](TableReader& r, Reading& st, const std::string& k) { st.s.setup.dt = r.positive(k); },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.setup.dt); }},
    {"duration",
     "number (s)",
     {"s", "`> 0`; at least one step", "required", "simulated time"},
     [](TableReader& r, Reading& st, const std::string& k) { st.s.run.duration_s = r.positive(k); },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.duration_s);
     }},
    {"production_start",
     "number (s)",
     {"s", "`[0, time.duration)`", "`time.duration / 2`", "fields average over [start, duration]"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double duration = st.s.run.duration_s;
       const double start = st.s.run.production_start_s = r.number(k, 0.5 * duration);
       // Both keys named, time.duration first: the window is empty when either is wrong,
       // and a --resume that shortens time.duration meets this before the checkpoint.
       if (!(start >= 0 && start < duration))
         throw UserError(fmt::format(
             "scene keys 'time.duration' = {} s and '{}' = {} s: the production window "
             "[production_start, duration) is empty; time.production_start must be in [0, {})",
             duration, r.key(k), start, duration));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.production_start_s);
     }},
};
const Table kTime = table("time", kTimeKeys);

// ---- [output] ----------------------------------------------------------------------------

const Key kOutputKeys[] = {
    {"snapshot_interval",
     "number (s)",
     {"s", "`> 0`; at most 1e5 snapshots", "`time.duration / 10`", "particle snapshots in run.h5"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.snapshot_interval_s = r.positive(k, st.s.run.duration_s / 10);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.snapshot_interval_s);
     }},
    {"series_interval",
     "number (s)",
     {"s", "`> 0`; at most 1e7 rows", "`time.duration / 200`", "time-series rows"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.series_interval_s = r.positive(k, st.s.run.duration_s / 200);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.series_interval_s);
     }},
    {"checkpoint_interval",
     "number (s)",
     {"s", "`> 0`; at most 1e5 checkpoints", "`time.duration / 5`",
      "checkpoint.h5 (also at the end and on SIGINT/SIGTERM)"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.checkpoint_interval_s = r.positive(k, st.s.run.duration_s / 5);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.checkpoint_interval_s);
     }},
    {"progress_interval",
     "number (s)",
     {"s (wall clock)", "`[0.01, 1e9]`", "`2`", "wall-clock seconds between progress lines"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.progress_interval_s = r.number_within(k, kProgressInterval.lo, kProgressInterval.hi,
                                                      2.0, kProgressInterval.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.run.progress_interval_s);
     }},
    {"sample_every",
     "integer",
     {"steps", "`>= 1`; enough samples (scene_format.md, \"Field sampling\")", "`100`",
      "steps between field samples"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.run.sample_every = r.integer_at_least(k, 1, 100);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, std::int64_t(w.s.run.sample_every));
     }},
    {"blocks",
     "integer",
     {"", "`[2, 10000]`; enough samples (scene_format.md, \"Field sampling\")", "`10`",
      "the production window is cut into this many blocks for error bars"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const long blocks = r.integer_at_least(k, 2, 10);
       if (blocks > kMaxBlocks)
         fail(r.key(k), std::to_string(blocks),
              fmt::format("must be at most {} (each block keeps its own bin sums)", kMaxBlocks));
       st.s.run.blocks = int(blocks);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, std::int64_t(w.s.run.blocks));
     }},
};
const Table kOutput = table("output", kOutputKeys);

// Every table, in the order of docs/scene_keys.md.
const Table* const kTables[] = {&kScene,  &kUnits,    &kMaterial, &kSpecies, &kContact, &kPair,
                                &kDomain, &kObstacle, &kInflow,   &kTime,    &kOutput,  &kNumerics};

}  // namespace

Scene read_scene(const toml::table& root) {
  Scene s;
  Reading st(s);
  TableReader top(&root, "", 1.0);
  read_table(top, st, kUnits);  // first: lengths elsewhere may be written in d
  read_table(top, st, kScene);
  read_materials(top, st);
  read_species(top, st);
  read_table(top, st, kContact);
  read_table(top, st, kNumerics);
  read_table(top, st, kDomain);
  read_table(top, st, kInflow);
  if (const toml::table* obstacle = top.table(kObstacle.name)) {
    TableReader r(obstacle, kObstacle.name, s.d_m);
    read_keys(r, st, kObstacle);
  }
  read_table(top, st, kTime);
  read_table(top, st, kOutput);
  top.finish();
  with_law_parameters(s.setup.contacts.model, [&](auto parameters) {
    for (std::size_t i = 0; i < parameters.keys.size(); ++i)
      s.setup.contacts.options.law_parameters[i] =
          st.law_parameters[i].value_or(s.inflow.speed_m_per_s);  // Default::inflow_speed
  });
  s.setup.contacts.calibration_speed_m_per_s =
      st.calibration_speed.value_or(s.inflow.speed_m_per_s);
  return s;
}

toml::table write_scene(const Scene& s) {
  const Writing w{s};
  toml::table root;
  for (const Table* t :
       {&kScene, &kUnits, &kContact, &kNumerics, &kDomain, &kInflow, &kTime, &kOutput})
    root.insert(t->name, write_keys(w, *t));
  toml::table materials;
  toml::array species;
  for (std::size_t a = 0; a < s.setup.species.size(); ++a) {
    Writing item = w;
    item.species = a;
    item.material = &s.setup.species[a].material;
    materials.insert_or_assign(item.material->name, write_keys(item, kMaterial));
    species.push_back(write_keys(item, kSpecies));
  }
  if (s.setup.obstacle) {
    Writing item = w;
    item.material = &s.setup.obstacle->material;
    materials.insert_or_assign(item.material->name, write_keys(item, kMaterial));
    root.insert(kObstacle.name, write_keys(w, kObstacle));
  }
  root.insert("materials", materials);
  root.insert("species", species);
  return root;
}

}  // namespace scene_toml

std::vector<SceneKey> scene_keys() {
  std::vector<SceneKey> keys;
  for (const scene_toml::Table* t : scene_toml::kTables) {
    const std::string prefix = std::string(t->name) + (t->name[0] == '[' ? " " : ".");
    for (const scene_toml::Key& k : *t)
      if (k.type) keys.push_back({prefix + k.name, k.type, k.doc});
  }
  return keys;
}

}  // namespace granshock

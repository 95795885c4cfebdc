// The scene schema's sections of the scene and its particles: [units], [scene],
// [materials.NAME] and [[species]] (io/scene_schema_parts.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_schema_parts.hpp"
#include "io/table_reader.hpp"

namespace granshock::scene_toml::schema_detail {

namespace {

// The most species a scene may have (docs/scene_format.md, "Limits"). Every pair has its
// own contact table, written in full into the resolved scene (about 160 KB of TOML at 64
// species, 2.4 MB at 256: past the 1 MiB a scene file may hold), kept as the force
// kernel's coefficient table (200 KB at 64, in cache) and collided twice for summary.json;
// the field sums grow with the species as well. The paper's mixture has two.
constexpr long kMaxSpecies = 64;

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
     {"", "2, 3", "`2`",
      "2: quasi-2-D (centres in the x-y plane); 3: spheres in a layer `domain.thickness` deep "
      "(scene_format.md, \"Three dimensions\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const long dim = r.integer_at_least(k, 2, 2);
       if (dim != 2 && dim != 3) fail(r.key(k), std::to_string(dim), "must be 2 (quasi-2-D) or 3");
       st.s.setup.dim = int(dim);
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

}  // namespace

const Table kUnits = table("units", kUnitsKeys);
const Table kScene = table("scene", kSceneKeys);
const Table kMaterial = table("materials.NAME", kMaterialKeys);
const Table kSpecies = table("[[species]]", kSpeciesKeys);

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

}  // namespace granshock::scene_toml::schema_detail

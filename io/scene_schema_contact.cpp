// The scene schema's sections of the contacts and the numerics: [contact], with every law's
// parameter keys and the pair tables [contact.pairs."a-b"], and [numerics]
// (io/scene_schema_parts.hpp).
#include <fmt/format.h>

#include <iterator>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "io/scene_schema_parts.hpp"
#include "io/table_reader.hpp"
#include "models/law_parameters.hpp"

namespace granshock::scene_toml::schema_detail {

namespace {

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

// The parameter keys of the contact laws, each declared once in its law's parameter
// header (models/law_parameters.hpp) and found there by name: read when the
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

}  // namespace

const Table kPair = table("contact.pairs.\"a-b\"", kPairKeys);
const Table kContact = {"contact", kContactKeyList.data(), kContactKeyList.size(), nullptr};
const Table kNumerics = table("numerics", kNumericsKeys);

}  // namespace granshock::scene_toml::schema_detail

// The scene schema: one table of keys per TOML table of a scene file (docs/scene_format.md,
// "Keys"). Each key is declared once, in its section's file (io/scene_schema_*.cpp), with
// its reader (type, default, limits, the message of a refusal) and its writer (the resolved
// scene). This file holds what walks them: read_scene and write_scene walk the same tables;
// scene_keys() lists them for the test that docs/scene_format.md documents exactly these
// keys (tests/scene/test_scene_schema.cpp).
#include "io/scene_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_file.hpp"
#include "io/scene_schema_parts.hpp"
#include "io/table_reader.hpp"
#include "models/law_parameters.hpp"

namespace granshock {
namespace scene_toml {

namespace schema_detail {

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

std::string unit_of_type(const std::string& type) {
  const std::size_t open = type.find('('), close = type.rfind(')');
  return open == std::string::npos || close < open ? "" : type.substr(open + 1, close - open - 1);
}

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

// Every table, in the order of docs/scene_keys.md.
const Table* const kTables[] = {&kScene,  &kUnits,    &kMaterial, &kSpecies, &kContact, &kPair,
                                &kDomain, &kObstacle, &kInflow,   &kTime,    &kOutput,  &kNumerics};

}  // namespace schema_detail

using namespace schema_detail;

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
  for (const scene_toml::schema_detail::Table* t : scene_toml::schema_detail::kTables) {
    const std::string prefix = std::string(t->name) + (t->name[0] == '[' ? " " : ".");
    for (const scene_toml::schema_detail::Key& k : *t)
      if (k.type) keys.push_back({prefix + k.name, k.type, k.doc});
  }
  return keys;
}

}  // namespace granshock

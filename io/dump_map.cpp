#include "io/dump_map.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <cmath>
#include <cstdlib>

#include "core/user_error.hpp"
#include "io/regular_file.hpp"
#include "io/scene_schema.hpp"

namespace granshock {

namespace {

long parse_type(const std::string& key, const std::string& origin) {
  char* end = nullptr;
  const long type = std::strtol(key.c_str(), &end, 10);
  if (key.empty() || *end != '\0' || type < 1)
    throw UserError(
        fmt::format("{}: [dump.types] key '{}' is not an atom type (a whole number "
                    ">= 1)",
                    origin, key));
  return type;
}

int species_index(const Scene& scene, const std::string& name, const std::string& origin,
                  long type) {
  std::string names;
  for (std::size_t a = 0; a < scene.setup.species.size(); ++a) {
    if (scene.setup.species[a].name == name) return static_cast<int>(a);
    names += (a ? ", " : "") + scene.setup.species[a].name;
  }
  throw UserError(fmt::format("{}: [dump.types] {} = '{}' is not a species of the scene ({})",
                              origin, type, name, names));
}

}  // namespace

DumpMap parse_dump_map(const std::string& text, const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: not valid TOML: {}", origin, e.source().begin.line,
                                e.source().begin.column, std::string(e.description())));
  }
  const toml::table* dump = root["dump"].as_table();
  if (dump == nullptr)
    throw UserError(origin +
                    ": no [dump] table (it maps the dump's atom types to the scene's "
                    "species; docs/fields.md, \"Fields from LAMMPS or LIGGGHTS dumps\")");
  const toml::table dump_table = *dump;
  root.erase("dump");

  DumpMap map;
  map.scene.as_given = text;
  map.scene.scene = scene_toml::read_scene(root);
  resolve_inflow(map.scene.scene);
  map.scene.resolved = scene_to_toml(map.scene.scene);

  const toml::table* types = nullptr;
  for (const auto& [key, value] : dump_table) {
    const std::string k(key.str());
    if (k == "types") {
      types = value.as_table();
      if (types == nullptr) throw UserError(origin + ": [dump] types must be a table");
    } else if (k == "dt") {
      const std::optional<double> dt = value.value<double>();
      if (!dt || !std::isfinite(*dt) || !(*dt > 0))
        throw UserError(origin + ": [dump] dt must be a positive number of seconds");
      map.dt = *dt;
    } else if (k == "flow_start") {
      const std::optional<double> t = value.value<double>();
      if (!t || !std::isfinite(*t))
        throw UserError(origin + ": [dump] flow_start must be a number of seconds");
      map.flow_start = *t;
    } else {
      throw UserError(origin + ": unknown key [dump] " + k + " (accepted: types, dt, flow_start)");
    }
  }
  if (types == nullptr || types->empty())
    throw UserError(origin +
                    ": [dump.types] is missing or empty: name the species of each "
                    "atom type, e.g. 1 = \"steel\"");
  for (const auto& [key, value] : *types) {
    const long type = parse_type(std::string(key.str()), origin);
    const std::optional<std::string> name = value.value<std::string>();
    if (!name)
      throw UserError(fmt::format("{}: [dump.types] {} must be a species name", origin, type));
    map.species_of_type[type] = species_index(map.scene.scene, *name, origin, type);
  }
  return map;
}

DumpMap load_dump_map(const std::filesystem::path& path) {
  const std::string text = read_regular_file(path, "dump map", kMaxSceneFileBytes);
  return parse_dump_map(text, path.string());
}

}  // namespace granshock

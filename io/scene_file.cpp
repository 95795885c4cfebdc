// Scene files: the TOML text, --set overrides, the scene read with the schema
// (scene_schema.cpp) and the resolved scene written back with it (docs/scene_format.md).
#include "io/scene_file.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <set>
#include <sstream>

#include "core/user_error.hpp"
#include "io/regular_file.hpp"
#include "io/scene_schema.hpp"
#include "io/shortest_floats.hpp"
#include "io/table_reader.hpp"
#include "models/law_parameters.hpp"

namespace granshock {

namespace {

using scene_toml::clip;

// --set key=value: the value is read as TOML (so 0.5, true, "x", [1, 2] work) and taken
// as a plain string when it is not valid TOML (so 50 d works without quotes).
void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw UserError(
        fmt::format("--set '{}': expected key=value (e.g. inflow.mach=13.7)", clip(assignment)));
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    parsed.insert_or_assign("v", text);
  }
  std::vector<std::string> parts;
  std::istringstream in(path);
  for (std::string p; std::getline(in, p, '.');) parts.push_back(p);
  toml::node* here = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (auto* t = here->as_table()) {
      if (!t->contains(parts[i])) t->insert(parts[i], toml::table{});
      here = t->get(parts[i]);
    } else if (auto* a = here->as_array()) {
      char* end = nullptr;
      const long index = std::strtol(parts[i].c_str(), &end, 10);
      if (*end || index < 0 || std::size_t(index) >= a->size())
        throw UserError(fmt::format("--set '{}': '{}' is not an index of this array (0..{})",
                                    clip(assignment), clip(parts[i]), a->size() - 1));
      here = a->get(std::size_t(index));
    } else {
      throw UserError(
          fmt::format("--set '{}': '{}' is not a table", clip(assignment), clip(parts[i])));
    }
  }
  auto* target = here->as_table();
  if (!target)
    throw UserError(fmt::format("--set '{}': the parent of '{}' is not a table", clip(assignment),
                                clip(parts.back())));
  target->insert_or_assign(parts.back(), *parsed.get("v"));
}

}  // namespace

LoadedScene parse_scene(const std::string& text, const std::vector<std::string>& overrides,
                        const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: not valid TOML: {}", clip(origin), e.source().begin.line,
                                e.source().begin.column, clip(std::string(e.description()))));
  }
  for (const auto& o : overrides) apply_override(root, o);

  LoadedScene out;
  out.as_given = text;
  out.scene = scene_toml::read_scene(root);
  resolve_inflow(out.scene);
  out.resolved = scene_to_toml(out.scene);
  return out;
}

namespace {
void collect_differences(const toml::node* a, const toml::node* b, const std::string& key,
                         std::set<std::string>& out) {
  const toml::table* ta = a ? a->as_table() : nullptr;
  const toml::table* tb = b ? b->as_table() : nullptr;
  if (ta && tb) {
    std::set<std::string> names;
    for (const auto& [k, v] : *ta) names.insert(std::string(k.str()));
    for (const auto& [k, v] : *tb) names.insert(std::string(k.str()));
    for (const auto& name : names)
      collect_differences(ta->get(name), tb->get(name), key.empty() ? name : key + "." + name, out);
    return;
  }
  const toml::array* aa = a ? a->as_array() : nullptr;
  const toml::array* ab = b ? b->as_array() : nullptr;
  if (aa && ab && aa->size() == ab->size()) {
    for (std::size_t i = 0; i < aa->size(); ++i)
      collect_differences(aa->get(i), ab->get(i), key + "." + std::to_string(i), out);
    return;
  }
  if (toml::node_view<const toml::node>{a} != toml::node_view<const toml::node>{b}) out.insert(key);
}
}  // namespace

std::vector<std::string> differing_keys(const std::string& toml_a, const std::string& toml_b) {
  toml::table a, b;
  try {
    a = toml::parse(toml_a);
    b = toml::parse(toml_b);
  } catch (const toml::parse_error&) {
    return {"(the scene text)"};
  }
  std::set<std::string> keys;
  collect_differences(&a, &b, "", keys);
  return {keys.begin(), keys.end()};
}

std::string without_other_laws_keys(const std::string& resolved) {
  toml::table root;
  try {
    root = toml::parse(resolved);
  } catch (const toml::parse_error&) {
    return resolved;
  }
  toml::table* contact = root["contact"].as_table();
  if (!contact) return resolved;
  ContactModelKind model = ContactModelKind::hertz;
  if (const std::optional<std::string> name = (*contact)["model"].value<std::string>()) {
    try {
      model = parse_contact_model(*name);
    } catch (const std::exception&) {
      return resolved;  // the scene's reader names the model
    }
  }
  std::set<std::string> own;
  with_law_parameters(model, [&](auto parameters) {
    for (const LawKey& k : parameters.keys) own.insert(k.name);
  });
  bool removed = false;
  for_each_law_parameters([&](auto parameters) {
    for (const LawKey& k : parameters.keys)
      if (!own.count(k.name) && contact->contains(k.name)) {
        contact->erase(std::string_view(k.name));
        removed = true;
      }
  });
  if (!removed) return resolved;
  std::ostringstream os;
  os << root << "\n";
  return with_shortest_floats(os.str());
}

LoadedScene load_scene_file(const std::filesystem::path& path,
                            const std::vector<std::string>& overrides) {
  // Bounded read: a scene is a short text, and a huge file must not hang us.
  const std::string text = read_regular_file(path, "scene file", kMaxSceneFileBytes);
  return parse_scene(text, overrides, path.string());
}

std::string scene_to_toml(const Scene& s) {
  std::ostringstream os;
  os << scene_toml::write_scene(s) << "\n";
  return with_shortest_floats(os.str());
}

}  // namespace granshock

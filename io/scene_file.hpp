// Scene files (TOML) for `granshock run`: parsing, `--set key=value` overrides, and
// validation. Every key is checked: an unknown, missing, mistyped or out-of-range key
// ends in a UserError naming the key, the value and what is accepted. The format is
// documented in docs/scene_format.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace granshock {

struct LoadedScene {
  Scene scene;
  std::string as_given;  // the file's text
  std::string resolved;  // every key with its value in SI units, after overrides and defaults
};

// The longest scene file load_scene_file reads (1 MiB).
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t(1) << 20;

LoadedScene load_scene_file(const std::filesystem::path& path,
                            const std::vector<std::string>& overrides);
LoadedScene parse_scene(const std::string& text, const std::vector<std::string>& overrides = {},
                        const std::string& origin = "scene");

// The dotted keys whose values differ between two scene TOML texts (a key present in one
// only counts), in sorted order; for naming what changed between a run and its resume.
std::vector<std::string> differing_keys(const std::string& toml_a, const std::string& toml_b);

// A resolved scene as a format-3 checkpoint may have stored it, read as today's: the
// parameter keys of contact laws other than its contact.model removed (a hertz scene's
// contact.characteristic_velocity, written for every law before each law owned its keys:
// models/law_parameters.hpp). Text that holds none, or is not TOML, comes back
// as it is.
std::string without_other_laws_keys(const std::string& resolved);

// The canonical TOML of a scene (SI units); parse_scene of it gives the same scene.
std::string scene_to_toml(const Scene& scene);

// What docs/scene_keys.md says of a key besides its name and type, in Markdown: its unit,
// what is accepted, its default ("required", a literal, another key) and what it does.
// Declared beside the key's reader (io/scene_schema_*.cpp), or by the law or shape that
// owns the key (models/law_key.hpp, shape_key.hpp).
struct KeyDoc {
  std::string unit, accepted, fallback, meaning;
};

// A key a scene file accepts, named as docs/scene_keys.md names it
// ("inflow.mach", "materials.NAME.density", "[[species]] diameter"), with the type that
// table gives it ("length", "number (m/s)") and the rest of its row.
struct SceneKey {
  std::string name;
  std::string type;
  KeyDoc doc;
};
// Every key of the scene schema, in the order of docs/scene_keys.md (defined in
// scene_schema.cpp, from the tables of the schema's sections).
std::vector<SceneKey> scene_keys();

// The table of docs/scene_keys.md's "Keys" section, made from scene_keys(): a header row
// and one row per key. `granshock keys` prints it; a test compares it with the docs.
std::string scene_keys_table();

}  // namespace granshock

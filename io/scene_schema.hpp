// The keys of a scene file, each declared once (io/scene_schema_*.cpp): its name, its type as
// docs/scene_keys.md gives it, how it is read and checked into a Scene and how
// it is written back from one. Reading and writing walk the same tables, so every key that
// is read is written back. Host code only: toml++ does not compile as CUDA
// (io/CMakeLists.txt); scene_keys() (scene_file.hpp) lists the tables without toml++.
#pragma once

#include <toml++/toml.h>

#include "core/scene.hpp"

namespace granshock::scene_toml {

// The scene of a TOML root (after --set overrides): every table read with its defaults
// and checks, in the order the checks depend on ([units] first, [[species]] before the
// keys whose defaults or limits depend on the diameters). The inflow is not yet resolved
// (resolve_inflow).
Scene read_scene(const toml::table& root);

// The TOML of a resolved scene: every key with its value in SI units; a Mach number is
// written as the sigma it gives, a species' or the obstacle's material under its name.
toml::table write_scene(const Scene& scene);

}  // namespace granshock::scene_toml

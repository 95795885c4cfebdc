// One parameter key of a contact law (docs/scene_format.md, [contact]): each law with
// parameters declares them in its parameter header (hooke_parameters.hpp,
// linear_parameters.hpp), and the scene schema (io/scene_schema.cpp), `collide`'s options,
// the resolved scene and docs/scene_keys.md's checks walk those lists. A key's value is
// kept in ContactOptions::law_parameters at the key's index (core/contact_settings.hpp).
// Plain C++: the scene reader includes it.
#pragma once

#include <array>
#include <cstddef>

#include "core/contact_settings.hpp"

namespace granshock {

struct LawKey {
  enum class Default {
    required,      // no default: a scene of the law must give it
    inflow_speed,  // the inflow speed (collide: --speed)
  };
  const char* name;  // contact.<name>; collide's option --<name with - for _>
  const char* type;  // the type column of docs/scene_keys.md, e.g. "number (N/m)"
  const char* meaning;
  double lo, hi;    // accepted: [lo, hi]
  const char* why;  // why the range, as a refusal says
  Default fallback = Default::required;
};

// A law without parameters (hertz: everything comes from the materials).
struct NoLawParameters {
  static constexpr std::array<LawKey, 0> keys{};
};

}  // namespace granshock

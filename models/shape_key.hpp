// One size key of an obstacle shape (docs/scene_format.md, [obstacle]): each shape's header
// lists its keys in `keys`, and the scene schema (io/scene_schema.cpp), the resolved scene,
// docs/scene_keys.md's check and the shape's own accessors all walk that list. A key's
// value is kept in Obstacle::size at the key's index in the list (core/obstacle.hpp).
// Plain C++, like the shapes: the scene reader includes it.
#pragma once

#include <cmath>
#include <limits>

namespace granshock {

struct ShapeKey {
  enum class Kind {
    length,  // a length (m, or "N d"), at least the largest particle diameter: the
             // contact law treats the obstacle as a wall (core/pair_properties.hpp)
    angle,   // degrees in (lo, hi), or [lo, hi) with lo_closed
  };
  const char* name;  // obstacle.<name>
  Kind kind;
  const char* meaning;
  double lo = 0, hi = 0;  // angle: its range
  bool lo_closed = false;
  // The value when the key is absent; NaN: required.
  double fallback = std::numeric_limits<double>::quiet_NaN();

  bool required() const { return std::isnan(fallback); }
  // The type column of docs/scene_keys.md.
  const char* type() const { return kind == Kind::angle ? "number (degrees)" : "length"; }
};

}  // namespace granshock

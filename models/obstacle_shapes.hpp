// The obstacle shapes granshock knows, and the host-side questions asked of a scene's
// obstacle (docs/design.md, "Obstacles"). A shape's header gives its size keys and its
// outline; every measure below follows from the outline (models/shape_outline.hpp),
// so no file outside a shape's header knows how a shape is measured. Plain C++ without
// Kokkos: the scene reader, the checkpoint checks, the inflow and the field analysis ask
// here. A new shape is one header, its enumerator and name (core/obstacle.hpp,
// core/variant_names.hpp) and one entry in ObstacleShapes below (docs/design.md, "Adding
// an obstacle shape").
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/obstacle.hpp"
#include "core/variant_names.hpp"
#include "models/cylinder.hpp"
#include "models/plate.hpp"
#include "models/shape_key.hpp"
#include "models/shape_outline.hpp"
#include "models/sphere.hpp"
#include "models/square.hpp"
#include "models/wedge.hpp"

namespace granshock {

template <class... Shapes>
struct ShapeList {};

using ObstacleShapes = ShapeList<CylinderShape, WedgeShape, PlateShape, SquareShape, SphereShape>;

namespace shapes_detail {

template <class... Shapes>
constexpr int shapes_of_kind(ObstacleShape kind, ShapeList<Shapes...>) {
  return ((Shapes::kind == kind ? 1 : 0) + ... + 0);
}

constexpr bool every_name_has_one_shape() {
  for (const ChoiceName<ObstacleShape>& c : Choices<ObstacleShape>::table)
    if (shapes_of_kind(c.value, ObstacleShapes{}) != 1) return false;
  return true;
}

template <class... Shapes>
constexpr bool every_shape_fits_its_sizes(ShapeList<Shapes...>) {
  return ((std::size(Shapes::keys) <= std::size_t(kMaxShapeSizes)) && ...);
}

template <class F, class Shape, class... Rest>
decltype(auto) with_shape_of_kind(ObstacleShape kind, F& f, ShapeList<Shape, Rest...>) {
  if constexpr (sizeof...(Rest) == 0) {
    if (kind != Shape::kind) throw std::logic_error("with_obstacle_shape: unknown shape");
    return f(Shape{});
  } else {
    if (kind == Shape::kind) return f(Shape{});
    return with_shape_of_kind(kind, f, ShapeList<Rest...>{});
  }
}

template <class F, class... Shapes>
void each_shape(F& f, ShapeList<Shapes...>) {
  (f(Shapes{}), ...);
}

}  // namespace shapes_detail

static_assert(shapes_detail::every_name_has_one_shape(),
              "every obstacle shape of core/variant_names.hpp needs exactly one type in "
              "ObstacleShapes (models/obstacle_shapes.hpp)");
static_assert(shapes_detail::every_shape_fits_its_sizes(ObstacleShapes{}),
              "a shape has more size keys than Obstacle::size holds: raise kMaxShapeSizes "
              "(core/obstacle.hpp)");

// Calls f(Shape{}) for the obstacle's shape.
template <class F>
decltype(auto) with_obstacle_shape(ObstacleShape kind, F&& f) {
  return shapes_detail::with_shape_of_kind(kind, f, ObstacleShapes{});
}
template <class F>
decltype(auto) with_obstacle_shape(const Obstacle& o, F&& f) {
  return with_obstacle_shape(o.shape, f);
}
// Calls f(Shape{}) for every shape, in the order of ObstacleShapes.
template <class F>
void for_each_obstacle_shape(F&& f) {
  shapes_detail::each_shape(f, ObstacleShapes{});
}

// The index of the key `name` among the size keys of `shape`; nullopt where it has none so
// named.
inline std::optional<std::size_t> shape_key_index(ObstacleShape shape, const std::string& name) {
  return with_obstacle_shape(shape, [&](auto s) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < std::size(s.keys); ++i)
      if (name == s.keys[i].name) return i;
    return std::nullopt;
  });
}

// The shapes with a size key `name`, in the order of ObstacleShapes (as refusals name them).
inline std::vector<ObstacleShape> shapes_with_key(const std::string& name) {
  std::vector<ObstacleShape> shapes;
  for_each_obstacle_shape([&](auto s) {
    if (shape_key_index(s.kind, name)) shapes.push_back(s.kind);
  });
  return shapes;
}

// An obstacle of `shape` at `centre` with the sizes in the order of the shape's keys (the
// keys' defaults where `sizes` stops short).
inline Obstacle make_obstacle(ObstacleShape shape, std::array<double, 3> centre,
                              std::initializer_list<double> sizes, Material material = {}) {
  Obstacle o;
  o.shape = shape;
  o.centre = centre;
  o.material = material;
  with_obstacle_shape(shape, [&](auto s) {
    if (sizes.size() > std::size(s.keys))
      throw std::logic_error("make_obstacle: more sizes than the shape has keys");
    for (std::size_t k = 0; k < std::size(s.keys); ++k)
      o.size[k] = k < sizes.size() ? sizes.begin()[k] : s.keys[k].fallback;
  });
  return o;
}

// The cross-section the force kernel and insertion work with (shape_outline.hpp).
inline ShapeOutline obstacle_outline(const Obstacle& o) {
  return with_obstacle_shape(o, [&](auto s) { return s.outline(o); });
}
// Across the flow (x): the D of delta/D (docs/fields.md).
inline double obstacle_frontal_width(const Obstacle& o) {
  return outline_extent(obstacle_outline(o), 0);
}
// Along the flow (y): the shape spans centre +- half of it.
inline double obstacle_streamwise_length(const Obstacle& o) {
  return outline_extent(obstacle_outline(o), 1);
}
// Its cross-section's area (m^2).
inline double obstacle_area(const Obstacle& o) {
  return outline_area(obstacle_outline(o));
}
// y of the upstream face on the stagnation line x = centre[0].
inline double obstacle_upstream_face(const Obstacle& o) {
  return o.centre[1] - 0.5 * obstacle_streamwise_length(o);
}
// y of the downstream face.
inline double obstacle_downstream_face(const Obstacle& o) {
  return o.centre[1] + 0.5 * obstacle_streamwise_length(o);
}
// y of the upstream surface at x, when x lies within the frontal width.
inline bool obstacle_upstream_surface(const Obstacle& o, double x, double& y) {
  const double dx = x - o.centre[0];
  if (!(std::abs(dx) < 0.5 * obstacle_frontal_width(o))) return false;
  double from_centre = 0;
  if (!outline_upstream_surface(obstacle_outline(o), dx, from_centre)) return false;
  y = o.centre[1] + from_centre;
  return true;
}
// The signed distance of (x, y) from the surface: negative inside.
// The obstacle's size keys with their values, as a message names them: "diameter 0.01 m",
// "half_angle 30 deg, length 0.02 m".
inline std::string obstacle_size_text(const Obstacle& o) {
  return with_obstacle_shape(o, [&](auto s) {
    std::vector<std::string> sizes;
    for (std::size_t i = 0; i < std::size(s.keys); ++i)
      sizes.push_back(fmt::format("{} {} {}", s.keys[i].name, o.size[i],
                                  s.keys[i].kind == ShapeKey::Kind::angle ? "deg" : "m"));
    return fmt::format("{}", fmt::join(sizes, ", "));
  });
}
inline double obstacle_distance(const Obstacle& o, double x, double y) {
  return outline_distance(obstacle_outline(o), x - o.centre[0], y - o.centre[1]);
}
// In 3-D: a sphere's distance counts along z too; a prism's is its cross-section's.
inline double obstacle_distance_in_3d(const Obstacle& o, double x, double y, double z) {
  const ShapeOutline s = obstacle_outline(o);
  if (!s.ball) return outline_distance(s, x - o.centre[0], y - o.centre[1]);
  return std::sqrt(std::pow(x - o.centre[0], 2) + std::pow(y - o.centre[1], 2) +
                   std::pow(z - o.centre[2], 2)) -
         s.radius;
}
// The area of the slab y in [y_lo, y_hi] within `clearance` of the obstacle: what
// insertion's keep-out zone takes from the inflow's free area.
inline double obstacle_kept_out_area(const Obstacle& o, double clearance, double y_lo,
                                     double y_hi) {
  return outline_kept_out_area(obstacle_outline(o), clearance, y_lo - o.centre[1],
                               y_hi - o.centre[1]);
}

}  // namespace granshock

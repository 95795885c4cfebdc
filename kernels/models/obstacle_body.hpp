// The obstacle as the kernels see it (docs/design.md, "Obstacles"): one compiled type for
// every shape, so that shapes do not multiply the variant table. Its geometry is the
// shape's outline (models/shape_outline.hpp), a disk or a convex polygon, copied
// to the device at start-up (a sphere's disk measured along z too in 3-D); which of the two
// is a value read once per particle-obstacle
// check, not per pair. The disk is the cylinder's own arithmetic, unchanged; a polygon
// gives the closest point on its boundary, so a particle at a face is pushed along the
// face's normal and one at a corner away from the corner. The contact law is the same
// for every shape: only the overlap and the normal come from here.
#pragma once

#include <Kokkos_Core.hpp>
#include <optional>

#include "core/obstacle.hpp"
#include "kernels/device/device_math.hpp"
#include "kernels/device/position.hpp"
#include "kernels/device/vec.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock {

struct ObstacleBody {
  static constexpr const char* name = "obstacle";
  static constexpr bool present = true;
  static bool matches(const std::optional<Obstacle>& o) { return o.has_value(); }

  // Positions and the centre are Position (double); a particle's offset from the centre is
  // formed in Position and rounded to Real, the rest is Real (device/position.hpp).
  template <int Dim, class Real>
  struct Geometry {
    static constexpr int kMaxCorners = ShapeOutline::kMaxCorners;
    Vec<Dim, Position> centre;  // in 3-D centre[2] counts for a sphere only (prisms along z)
    bool polygon = false;
    bool ball = false;  // a sphere: in 3-D the distance along z counts
    Real radius;        // the disk's; for a polygon the radius of a circle about the centre
                        // that holds it, which no touching particle's offset is beyond
    int corners = 0;
    Real corner[kMaxCorners][2] = {};
    Real edge[kMaxCorners][2] = {};    // corner[e + 1] - corner[e]
    Real inv_len2[kMaxCorners] = {};   // 1 / |edge|^2
    Real normal[kMaxCorners][2] = {};  // outward unit normals

    static Geometry from(const std::optional<Obstacle>& o) {
      Geometry g;
      for (int d = 0; d < Dim; ++d) g.centre[d] = Position(o->centre[d]);
      const ShapeOutline s = obstacle_outline(*o);
      g.polygon = s.kind == ShapeOutline::Kind::polygon;
      g.ball = s.ball;
      if (!g.polygon) {
        g.radius = Real(s.radius);
        return g;
      }
      g.corners = s.corners;
      double reach = 0;
      for (int e = 0; e < s.corners; ++e) {
        const auto& a = s.corner[e];
        const auto& b = s.corner[(e + 1) % s.corners];
        const double ex = b[0] - a[0], ey = b[1] - a[1], len = std::sqrt(ex * ex + ey * ey);
        g.corner[e][0] = Real(a[0]), g.corner[e][1] = Real(a[1]);
        g.edge[e][0] = Real(ex), g.edge[e][1] = Real(ey);
        g.inv_len2[e] = Real(1 / (len * len));
        g.normal[e][0] = Real(ey / len), g.normal[e][1] = Real(-ex / len);
        reach = std::max(reach, std::sqrt(a[0] * a[0] + a[1] * a[1]));
      }
      g.radius = Real(reach);
      return g;
    }

    // Forced inline, like every per-pair or per-particle function of the force kernel: an
    // outlined call here was a large share of a step (docs/benchmarks.md, "Old against
    // new: the restructuring, and inlining"; cli.force_kernel_helpers_are_inlined checks it).
    // A particle of radius r at x touches the surface when its distance from it is below r:
    // then dn = r - distance and n is the unit vector from the closest surface point to x.
    KOKKOS_FORCEINLINE_FUNCTION bool touches(const Vec<Dim, Position>& x, Real r, Real& dn,
                                             Vec<Dim, Real>& n) const {
      Vec<Dim, Real> dx = to_real<Real>(x - centre);
      if constexpr (Dim == 3)
        if (!ball) dx[2] = 0;
      const Real r2 = dot(dx, dx);
      const Real reach = r + radius;
      if (r2 >= reach * reach) return false;
      if (!polygon) {
        // The disk: dn = r + R - |x - x_c|, n the radial unit vector.
        const Real dist = dmath::sqrt(r2);
        n = (Real(1) / dist) * dx;
        dn = reach - dist;
        return true;
      }
      return touches_polygon(dx, r, dn, n);
    }

    // The closest point on the polygon's boundary; a centre inside the polygon (a particle
    // pushed in past its radius) is pushed out through the face it is least deep behind.
    KOKKOS_FORCEINLINE_FUNCTION bool touches_polygon(const Vec<Dim, Real>& dx, Real r, Real& dn,
                                                     Vec<Dim, Real>& n) const {
      Real best = Real(-1), qx = 0, qy = 0, deepest = Real(0);
      int face = -1;
      for (int e = 0; e < corners; ++e) {
        const Real px = dx[0] - corner[e][0], py = dx[1] - corner[e][1];
        Real t = (px * edge[e][0] + py * edge[e][1]) * inv_len2[e];
        t = t < Real(0) ? Real(0) : (t > Real(1) ? Real(1) : t);
        const Real ox = px - t * edge[e][0], oy = py - t * edge[e][1];
        const Real d2 = ox * ox + oy * oy;
        if (best < Real(0) || d2 < best) best = d2, qx = ox, qy = oy;
        const Real s = px * normal[e][0] + py * normal[e][1];
        if (face < 0 || s > deepest) deepest = s, face = e;
      }
      n = Vec<Dim, Real>::zero();
      if (deepest <= Real(0)) {  // inside
        n[0] = normal[face][0], n[1] = normal[face][1];
        dn = r - deepest;
        return true;
      }
      if (best >= r * r) return false;
      const Real dist = dmath::sqrt(best);
      n[0] = qx / dist, n[1] = qy / dist;
      dn = r - dist;
      return true;
    }

    // Whether a particle's centre lies inside the body: a sphere's ball in 3-D, the
    // cross-section of a prism (or of a sphere in 2-D) otherwise.
    KOKKOS_FORCEINLINE_FUNCTION bool contains(const Vec<Dim, Position>& x) const {
      if constexpr (Dim == 3) {
        if (ball) {
          const Vec<Dim, Real> dx = to_real<Real>(x - centre);
          return dot(dx, dx) < radius * radius;
        }
      }
      return keeps_out(x[0], x[1], Real(0));
    }

    // Insertion places no centre within `clearance` of the surface (a sphere's whole
    // column in 3-D: no particle is placed above or below it).
    KOKKOS_FORCEINLINE_FUNCTION bool keeps_out(Position x0, Position x1, Real clearance) const {
      const Position cx = x0 - centre[0], cy = x1 - centre[1];
      const Position reach = Position(radius + clearance);
      if (!polygon || cx * cx + cy * cy >= reach * reach) return cx * cx + cy * cy < reach * reach;
      Vec<Dim, Real> dx = Vec<Dim, Real>::zero();
      dx[0] = Real(cx), dx[1] = Real(cy);
      Real dn;
      Vec<Dim, Real> n;
      return touches_polygon(dx, clearance, dn, n) && dn > Real(0);
    }
  };
};

}  // namespace granshock

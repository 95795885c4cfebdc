// The contact geometry of each obstacle shape (docs/design.md, "Obstacles") against hand
// geometry: the overlap and normal of a particle at a wedge face, the wedge tip, a plate
// face and a plate corner as the force kernel finds them (kernels/models/obstacle_body.hpp),
// and the free area the keep-out zone leaves (kernels/models/shape_outline.hpp) against
// Steiner's formula for a convex shape grown by a clearance.
#include <gtest/gtest.h>

#include <cmath>

#include "models/obstacle_body.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;

namespace {

constexpr double kTheta = 20 * M_PI / 180, kLength = 10e-3, kR = 0.5e-3, kDelta = 1e-5;

Obstacle wedge(double half_angle_deg = 20) {
  Obstacle o;
  o.shape = ObstacleShape::wedge;
  o.centre = {0.02, 0.03, 0};
  o.half_angle_deg = half_angle_deg;
  o.length_m = kLength;
  return o;
}

Obstacle plate(double width = 8e-3, double thickness = 2e-3) {
  Obstacle o;
  o.shape = ObstacleShape::plate;
  o.centre = {0.02, 0.03, 0};
  o.width_m = width;
  o.thickness_m = thickness;
  return o;
}

struct Touch {
  bool touches;
  double dn, nx, ny;
};

Touch touch(const Obstacle& o, double x, double y, double r = kR) {
  const auto g = ObstacleBody::Geometry<2, double>::from(o);
  double dn = 0;
  Vec<2, double> n = Vec<2, double>::zero();
  const bool t = g.touches(Vec<2, Position>{{x, y}}, r, dn, n);
  return {t, dn, n[0], n[1]};
}

// A particle whose centre is r - delta from `at` along the unit vector (ux, uy) overlaps
// the surface by delta with normal (ux, uy), when `at` is the closest surface point.
void expect_contact(const Obstacle& o, double ax, double ay, double ux, double uy) {
  const Touch t = touch(o, ax + (kR - kDelta) * ux, ay + (kR - kDelta) * uy);
  ASSERT_TRUE(t.touches);
  EXPECT_NEAR(t.dn, kDelta, 1e-12);
  EXPECT_NEAR(t.nx, ux, 1e-9);
  EXPECT_NEAR(t.ny, uy, 1e-9);
  EXPECT_FALSE(touch(o, ax + (kR + kDelta) * ux, ay + (kR + kDelta) * uy).touches);
}

}  // namespace

// The wedge's left face runs from the tip (xc, yc - L/2) along (-sin theta, cos theta);
// its outward normal is (-cos theta, -sin theta), upstream and outward.
TEST(ObstacleGeometry, WedgeFaceNormalIsPerpendicularToTheFace) {
  const Obstacle o = wedge();
  const double tx = o.centre[0], ty = o.centre[1] - 0.5 * kLength;
  const double along = 0.4 * kLength / std::cos(kTheta);  // 40 % of the way to the base
  const double ax = tx - along * std::sin(kTheta), ay = ty + along * std::cos(kTheta);
  expect_contact(o, ax, ay, -std::cos(kTheta), -std::sin(kTheta));
  expect_contact(o, 2 * o.centre[0] - ax, ay, std::cos(kTheta), -std::sin(kTheta));  // right
}

// At the tip every direction between the two faces' normals is a normal: the particle is
// pushed away from the tip along the line through its centre.
TEST(ObstacleGeometry, WedgeTipPushesAlongTheLineFromTheTip) {
  const Obstacle o = wedge();
  const double tx = o.centre[0], ty = o.centre[1] - 0.5 * kLength;
  expect_contact(o, tx, ty, 0, -1);
  const double a = 50 * M_PI / 180;  // 50 deg off the axis, inside the tip's 70 deg cone
  expect_contact(o, tx, ty, std::sin(a), -std::cos(a));
}

// The base closes the wedge: a particle behind it is pushed downstream.
TEST(ObstacleGeometry, WedgeBaseFacesDownstream) {
  const Obstacle o = wedge();
  expect_contact(o, o.centre[0] + 1e-3, o.centre[1] + 0.5 * kLength, 0, 1);
}

TEST(ObstacleGeometry, PlateFaceAndCorner) {
  const Obstacle o = plate();
  const double left = o.centre[0] - 4e-3, front = o.centre[1] - 1e-3;
  expect_contact(o, o.centre[0] + 1e-3, front, 0, -1);  // the face facing the flow
  expect_contact(o, left, o.centre[1], -1, 0);          // a side
  const double s = std::sqrt(0.5);
  expect_contact(o, left, front, -s, -s);  // the corner, along its diagonal
  const double a = 20 * M_PI / 180;        // and 20 deg off the upstream direction
  expect_contact(o, left, front, -std::sin(a), -std::cos(a));
}

// A centre pushed inside (past its radius) leaves through the nearest face.
TEST(ObstacleGeometry, CentreInsideLeavesThroughTheNearestFace) {
  const Obstacle o = plate();
  const Touch t = touch(o, o.centre[0] + 1e-3, o.centre[1] - 0.8e-3);
  ASSERT_TRUE(t.touches);
  EXPECT_NEAR(t.dn, kR + 0.2e-3, 1e-12);
  EXPECT_NEAR(t.nx, 0, 1e-12);
  EXPECT_NEAR(t.ny, -1, 1e-12);
}

// Insertion keeps centres out of the shape grown by the clearance, and no further.
TEST(ObstacleGeometry, KeepOutIsTheShapeGrownByTheClearance) {
  const Obstacle o = wedge();
  const auto g = ObstacleBody::Geometry<2, double>::from(o);
  const double tx = o.centre[0], ty = o.centre[1] - 0.5 * kLength, c = 1e-3;
  EXPECT_TRUE(g.keeps_out(tx, ty - 0.99 * c, c));
  EXPECT_FALSE(g.keeps_out(tx, ty - 1.01 * c, c));
  EXPECT_TRUE(g.keeps_out(o.centre[0], o.centre[1], 0));  // inside, clearance 0
  EXPECT_FALSE(g.keeps_out(tx, ty - 1e-6, 0));
}

// The frontal width, upstream face and area of each shape, by hand.
TEST(ObstacleGeometry, HostQuestionsByHand) {
  const Obstacle w = wedge();
  EXPECT_NEAR(obstacle_frontal_width(w), 2 * kLength * std::tan(kTheta), 1e-15);
  EXPECT_DOUBLE_EQ(obstacle_upstream_face(w), w.centre[1] - 0.5 * kLength);
  EXPECT_NEAR(obstacle_area(w), kLength * kLength * std::tan(kTheta), 1e-18);
  const Obstacle p = plate();
  EXPECT_DOUBLE_EQ(obstacle_frontal_width(p), 8e-3);
  EXPECT_DOUBLE_EQ(obstacle_upstream_face(p), p.centre[1] - 1e-3);
  EXPECT_DOUBLE_EQ(obstacle_area(p), 16e-6);
  double y = 0;
  ASSERT_TRUE(obstacle_upstream_surface(w, w.centre[0] + 1e-3, y));
  EXPECT_NEAR(y, w.centre[1] - 0.5 * kLength + 1e-3 / std::tan(kTheta), 1e-15);
  EXPECT_FALSE(obstacle_upstream_surface(p, p.centre[0] + 4.1e-3, y));
}

// Steiner: a convex shape of area A and perimeter P grown by c has area A + P c + pi c^2;
// a slab through part of it is checked against counting points on a fine grid.
TEST(ObstacleGeometry, KeptOutAreaIsSteinersFormula) {
  const double c = 1e-3;
  for (const Obstacle& o : {wedge(), wedge(60), plate(), plate(1e-3, 1e-3)}) {
    const double w = obstacle_frontal_width(o), l = obstacle_streamwise_length(o);
    const double perimeter = o.shape == ObstacleShape::plate
                                 ? 2 * (w + l)
                                 : w + 2 * l / std::cos(o.half_angle_deg * M_PI / 180);
    const double whole = obstacle_area(o) + perimeter * c + M_PI * c * c;
    EXPECT_NEAR(obstacle_kept_out_area(o, c, 0, 1), whole, 1e-6 * whole) << choice_name(o.shape);
    // The slab from 1 mm upstream of the face to the centre, by a grid of 4 um.
    const double y_lo = obstacle_upstream_face(o) - 1e-3, y_hi = o.centre[1], h = 4e-6;
    long inside = 0;
    for (double y = y_lo + 0.5 * h; y < y_hi; y += h)
      for (double x = o.centre[0] - 0.5 * w - 2 * c; x < o.centre[0] + 0.5 * w + 2 * c; x += h)
        inside += obstacle_distance(o, x, y) < c;
    const double counted = double(inside) * h * h;
    EXPECT_NEAR(obstacle_kept_out_area(o, c, y_lo, y_hi), counted, 2e-3 * counted)
        << choice_name(o.shape);
  }
}

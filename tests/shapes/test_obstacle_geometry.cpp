// The contact geometry of each obstacle shape (docs/design.md, "Obstacles") against hand
// geometry: the overlap and normal of a particle at a wedge face, the wedge tip, a plate
// face and a plate corner as the force kernel finds them (kernels/models/obstacle_body.hpp),
// and the free area the keep-out zone leaves (models/shape_outline.hpp) against
// Steiner's formula for a convex shape grown by a clearance; and, for every shape of
// ObstacleShapes, the measures the host derives from the outline (frontal width, length,
// area, upstream surface) against the signed distance the contact geometry uses.
#include <gtest/gtest.h>

#include <cmath>

#include "kernels/models/obstacle_body.hpp"
#include "models/obstacle_shapes.hpp"

using namespace granshock;

namespace {

constexpr double kTheta = 20 * M_PI / 180, kLength = 10e-3, kR = 0.5e-3, kDelta = 1e-5;

constexpr std::array<double, 3> kCentre = {0.02, 0.03, 0};

Obstacle wedge(double half_angle_deg = 20) {
  return make_obstacle(ObstacleShape::wedge, kCentre, {half_angle_deg, kLength});
}

Obstacle plate(double width = 8e-3, double thickness = 2e-3) {
  return make_obstacle(ObstacleShape::plate, kCentre, {width, thickness});
}

Obstacle square(double side = 6e-3, double rotation_deg = 0) {
  return make_obstacle(ObstacleShape::square, kCentre, {side, rotation_deg});
}

// An obstacle of the shape with sizes of its own keys: lengths from 6 mm up, angles in
// the middle of their range.
template <class Shape>
Obstacle example_of(Shape) {
  Obstacle o;
  o.shape = Shape::kind;
  o.centre = kCentre;
  for (std::size_t k = 0; k < std::size(Shape::keys); ++k) {
    const ShapeKey& key = Shape::keys[k];
    o.size[k] = key.kind == ShapeKey::Kind::angle ? 0.5 * (key.lo + key.hi) * 0.7
                                                  : 6e-3 * (1 + 0.5 * double(k));
  }
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

  const Obstacle c = make_obstacle(ObstacleShape::cylinder, kCentre, {5e-3});
  EXPECT_DOUBLE_EQ(obstacle_frontal_width(c), 5e-3);
  EXPECT_DOUBLE_EQ(obstacle_streamwise_length(c), 5e-3);
  EXPECT_DOUBLE_EQ(obstacle_area(c), M_PI * 2.5e-3 * 2.5e-3);
  ASSERT_TRUE(obstacle_upstream_surface(c, c.centre[0] + 1.5e-3, y));
  EXPECT_NEAR(y, c.centre[1] - 2e-3, 1e-15);  // the 3-4-5 triangle

  // A square with a face upstream is the plate of equal sides, corner for corner.
  const ShapeOutline face_on = obstacle_outline(square());
  const ShapeOutline as_plate = obstacle_outline(plate(6e-3, 6e-3));
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 2; ++a) EXPECT_EQ(face_on.corner[k][a], as_plate.corner[k][a]);
  // Turned by 45 degrees: a corner upstream, side sqrt(2) across and along.
  const Obstacle diamond = square(6e-3, 45);
  EXPECT_NEAR(obstacle_frontal_width(diamond), 6e-3 * std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(obstacle_streamwise_length(diamond), 6e-3 * std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(obstacle_area(diamond), 36e-6, 1e-18);
  ASSERT_TRUE(obstacle_upstream_surface(diamond, diamond.centre[0] + 1e-3, y));
  EXPECT_NEAR(y, diamond.centre[1] - 3e-3 * std::sqrt(2.0) + 1e-3, 1e-15);  // faces at 45 deg
}

// Every shape's frontal width, length, area and upstream surface, derived from its outline
// (models/shape_outline.hpp), against what the signed distance of the contact
// geometry says: the four lines the width and length put at the shape's sides touch it
// (the least distance along each is 0) and leave it on one side; the area is that of the
// points inside on a fine grid; the upstream surface is where the distance is 0 and the
// flow meets it first. A shape whose measures disagree with the surface the particles
// meet fails here, whatever its header says.
TEST(ObstacleGeometry, EveryShapesMeasuresAgreeWithItsSurface) {
  int shapes = 0;
  for_each_obstacle_shape([&](auto shape) {
    ++shapes;
    const Obstacle o = example_of(shape);
    const double w = obstacle_frontal_width(o), l = obstacle_streamwise_length(o);
    const double xc = o.centre[0], yc = o.centre[1], reach = 0.5 * std::hypot(w, l) + 1e-4;
    // The least distance from the shape along a line, on points dh apart: within dh/2 of
    // the true least distance (the distance changes at most as fast as the point moves).
    const double dh = 1e-7;
    const auto least_along_y = [&](double x) {  // the line x = const
      double least = 1;
      for (double y = yc - reach; y < yc + reach; y += dh)
        least = std::min(least, obstacle_distance(o, x, y));
      return least;
    };
    const auto least_along_x = [&](double y) {  // the line y = const
      double least = 1;
      for (double x = xc - reach; x < xc + reach; x += dh)
        least = std::min(least, obstacle_distance(o, x, y));
      return least;
    };
    EXPECT_NEAR(least_along_y(xc + 0.5 * w), 0, 0.5 * dh) << shape.name;
    EXPECT_NEAR(least_along_y(xc - 0.5 * w), 0, 0.5 * dh) << shape.name;
    EXPECT_NEAR(least_along_x(obstacle_upstream_face(o)), 0, 0.5 * dh) << shape.name;
    EXPECT_NEAR(least_along_x(obstacle_downstream_face(o)), 0, 0.5 * dh) << shape.name;
    EXPECT_NEAR(obstacle_downstream_face(o) - obstacle_upstream_face(o), l, 1e-15) << shape.name;
    // The area: points inside on a grid of step h, within the cells the perimeter (below
    // 2 (w + l) for a convex shape in a w x l box) crosses.
    const double h = 2e-5;
    long inside = 0;
    for (double y = yc - reach + 0.5 * h; y < yc + reach; y += h)
      for (double x = xc - reach + 0.5 * h; x < xc + reach; x += h)
        inside += obstacle_distance(o, x, y) < 0;
    EXPECT_NEAR(obstacle_area(o), double(inside) * h * h, 2 * (w + l) * h) << shape.name;
    // The upstream surface at lateral offsets across the width: the distance is zero there
    // and positive just upstream of it.
    for (double f : {0.0, 0.2, -0.45, 0.7, -0.9}) {
      const double x = xc + f * 0.5 * w;
      double y = 0;
      ASSERT_TRUE(obstacle_upstream_surface(o, x, y)) << shape.name << " at " << f;
      EXPECT_NEAR(obstacle_distance(o, x, y), 0, 1e-12) << shape.name << " at " << f;
      EXPECT_GT(obstacle_distance(o, x, y - 1e-6), 0) << shape.name << " at " << f;
    }
    double y = 0;
    EXPECT_FALSE(obstacle_upstream_surface(o, xc + 0.51 * w, y)) << shape.name;
  });
  EXPECT_EQ(shapes, int(std::size(Choices<ObstacleShape>::table)));
}

// Steiner: a convex shape of area A and perimeter P grown by c has area A + P c + pi c^2;
// a slab through part of it is checked against counting points on a fine grid.
TEST(ObstacleGeometry, KeptOutAreaIsSteinersFormula) {
  const double c = 1e-3;
  for (const Obstacle& o :
       {wedge(), wedge(60), plate(), plate(1e-3, 1e-3), square(4e-3, 30), square(4e-3, 45)}) {
    const double w = obstacle_frontal_width(o), l = obstacle_streamwise_length(o);
    double perimeter = 0;
    if (o.shape == ObstacleShape::plate) perimeter = 2 * (w + l);
    if (o.shape == ObstacleShape::square) perimeter = 4 * SquareShape::side(o);
    if (o.shape == ObstacleShape::wedge)
      perimeter = w + 2 * l / std::cos(WedgeShape::half_angle_deg(o) * M_PI / 180);
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

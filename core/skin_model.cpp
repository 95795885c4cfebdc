#include "core/skin_model.hpp"

#include <cmath>

namespace granshock {

namespace {

double ball(int dim, double radius) {
  constexpr double pi = 3.14159265358979323846;
  return dim == 2 ? pi * radius * radius : 4.0 / 3.0 * pi * radius * radius * radius;
}

}  // namespace

double SkinModel::cost(const SkinSample& at, double s) const {
  const double grow = std::pow((range + s) / (range + at.skin), dim);
  const double partners = at.partners_per_particle * grow;
  const double candidates =
      at.partners_per_particle * std::pow(3 * cell, dim) / ball(dim, range + at.skin);
  const double steps_between_builds = 0.5 * s / at.drift_per_step;
  return partners + (2 * candidates + build_overhead) / steps_between_builds;
}

// Golden-section search: a fixed number of steps, so the answer is a function of the
// sample alone. 60 steps shrink the interval by 0.618^60 ~ 3e-13.
double SkinModel::best(const SkinSample& at) const {
  if (!(at.drift_per_step > 0) || !(at.skin > 0) || !(largest > smallest))
    return at.skin > 0 ? std::fmin(std::fmax(at.skin, smallest), largest) : largest;
  const double ratio = 0.5 * (std::sqrt(5.0) - 1);
  double a = smallest, b = largest;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = cost(at, c), fd = cost(at, d);
  for (int k = 0; k < 60; ++k) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = cost(at, c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = cost(at, d);
    }
  }
  // An optimum at a bound is the bound itself, not a point 1e-13 inside: a skin held at
  // the largest is then bitwise the fixed skin, and its run the fixed-skin run.
  const double tolerance = 1e-9 * (largest - smallest);
  if (a <= smallest + tolerance) return smallest;
  if (b >= largest - tolerance) return largest;
  return 0.5 * (a + b);
}

}  // namespace granshock

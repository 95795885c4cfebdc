// The checks that need the solver the scene builds: its dimension, species, friction
// arrays, box and obstacle.
#include <algorithm>

#include "core/checkpoint_check_support.hpp"
#include "core/contact_settings.hpp"

namespace granshock {

using namespace checks;

namespace {

double norm(const std::vector<double>& v, std::size_t first, std::size_t count) {
  double sum = 0;
  for (std::size_t c = 0; c < count; ++c) sum += v[first + c] * v[first + c];
  return std::sqrt(sum);
}

// Coulomb's limit keeps k_t |xi| <= mu |F_n|, which keeps a spring shorter than mu times
// the overlap (E*/6G* < 1 for any Poisson ratio); 10 (1 + mu) diameters leave a wide
// margin for damping and rotation of the spring.
void check_spring_lengths(const SolverState& s, const SolverFit& fit) {
  const double d_max = 2 * largest(fit.radius);
  const double limit = 10 * (1 + fit.max_friction) * d_max;
  const std::size_t dim = std::size_t(s.dim);
  for (const auto& [name, values] :
       {std::pair<const char*, const std::vector<double>*>{"/state/history_spring",
                                                           &s.history_spring},
        {"/state/history_obstacle_spring", &s.history_obstacle_spring}}) {
    for (std::size_t k = 0; k + dim <= values->size(); k += dim) {
      const double length = norm(*values, k, dim);
      if (length > limit)
        fail(fmt::format("{} starts a spring {} m long, more than 10 (1 + mu) diameters ({} m)",
                         at(name, k), length, limit));
    }
  }
}

}  // namespace

void check_fit(const SolverState& s, const SolverFit& fit) {
  if (s.dim != fit.dim) fail(fmt::format("/state@dim = {}, but the scene is {}-D", s.dim, fit.dim));
  const int species = int(fit.radius.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.species[i] < 0 || s.species[i] >= species)
      fail(fmt::format("{} = {} is not a species of the scene (it has {})", at("/state/species", i),
                       s.species[i], species));
  if (s.history_slots != fit.history_slots)
    fail(fmt::format("/state@history_slots = {}, but this scene's solver keeps {} ({})",
                     s.history_slots, fit.history_slots,
                     fit.history_slots > 0 ? "friction" : "no friction"));
  if (fit.history_slots > 0)
    expect_size("/state/history_obstacle_spring", s.history_obstacle_spring,
                s.size() * std::size_t(s.dim), "this solver keeps a wall spring per particle");
  for (int d = 0; d < 3; ++d) {
    if (d < fit.dim && fit.delete_outside && !fit.box.periodic[std::size_t(d)]) continue;
    const char* why = d >= fit.dim                       ? "the scene has no such axis"
                      : fit.box.periodic[std::size_t(d)] ? "the axis is periodic"
                                                         : "the scene deletes no particles";
    if (s.removed_low[std::size_t(d)] != 0 || s.removed_high[std::size_t(d)] != 0)
      fail(fmt::format("/state@removed_low/high[{}] = {}/{}: nothing leaves through that face ({})",
                       d, s.removed_low[std::size_t(d)], s.removed_high[std::size_t(d)], why));
  }
  if (fit.history_slots > 0) check_spring_lengths(s, fit);
}

// The contact law's range (contact_settings.hpp): a state in which two particles overlap
// by more than kOverlapRefuse of the smaller diameter, or a centre lies inside the obstacle,
// was not made by the solver (insertion places no particle on another or in the keep-out
// zone; docs/stability.md), and resuming it would fling the particles apart.
template <class Distance>
void check_contact_range(const SolverState& s, const SolverFit& fit, std::size_t i,
                         const Distance& distance) {
  const std::size_t dim = std::size_t(s.dim);
  const double ri = fit.radius[std::size_t(s.species[i])];
  for (int k = s.neighbour_offsets[i]; k < s.neighbour_offsets[i + 1]; ++k) {
    const std::size_t j = std::size_t(s.neighbours[std::size_t(k)]);
    const double rj = fit.radius[std::size_t(s.species[j])];
    const double overlap = (ri + rj - distance(i, j)) / (2 * std::min(ri, rj));
    if (overlap > kOverlapRefuse)
      fail(
          fmt::format("particles {} and {} overlap by {:.3g} of a diameter, past the contact "
                      "law's range ({}): the state was not made by the solver",
                      s.id[i], s.id[j], overlap, kOverlapRefuse));
  }
  if (!fit.obstacle_distance) return;
  const double depth = -fit.obstacle_distance(&s.position[i * dim]);
  if (depth > 0)
    fail(
        fmt::format("particle {} lies inside the obstacle (its centre {:.3g} m inside the "
                    "surface): the state was not made by the solver",
                    s.id[i], depth));
}

void check_contacts(const SolverState& s, const SolverFit& fit) {
  const std::size_t dim = std::size_t(s.dim), slots = std::size_t(s.history_slots);
  const double r_max = largest(fit.radius);
  const double tol = fit.distance_tolerance;
  auto distance = [&](std::size_t i, std::size_t j) {
    double r2 = 0;
    for (std::size_t d = 0; d < dim; ++d) {
      double dx = s.position[i * dim + d] - s.position[j * dim + d];
      const double length = fit.box.length(int(d));
      if (fit.box.periodic[d]) dx -= length * std::rint(dx / length);
      r2 += dx * dx;
    }
    return std::sqrt(r2);
  };
  auto is_partner = [&](std::size_t i, int id) {
    for (std::size_t a = 0; a < slots; ++a)
      if (s.history_partner[i * slots + a] == id) return true;
    return false;
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    check_contact_range(s, fit, i, distance);
    // Near a face the last force may come from a partner deleted since (open axis) or
    // from the obstacle seen across the wrap (periodic axis): no conclusion there.
    bool near_face = false;
    for (std::size_t d = 0; d < dim; ++d) {
      const double x = s.position[i * dim + d];
      near_face = near_face || x - fit.box.lo[d] < 2.02 * r_max || fit.box.hi[d] - x < 2.02 * r_max;
    }
    if (near_face) continue;
    const double ri = fit.radius[std::size_t(s.species[i])];
    int contacts = 0;
    for (int k = s.neighbour_offsets[i]; k < s.neighbour_offsets[i + 1]; ++k) {
      const std::size_t j = std::size_t(s.neighbours[std::size_t(k)]);
      const double rsum = ri + fit.radius[std::size_t(s.species[j])];
      const double r = distance(i, j);
      if (r >= rsum + tol) continue;
      ++contacts;
      // The force kernel claims a history slot for every contact it computes.
      if (slots > 0 && r < rsum - tol && !is_partner(i, s.id[j]))
        fail(
            fmt::format("/state/history_partner of particle {} lacks particle {}, which it touches",
                        s.id[i], s.id[j]));
    }
    // ... and frees the slot of every contact that ended.
    for (std::size_t a = 0; a < slots; ++a) {
      const int partner = s.history_partner[i * slots + a];
      bool in_contact = partner < 0;
      for (int k = s.neighbour_offsets[i]; k < s.neighbour_offsets[i + 1] && !in_contact; ++k) {
        const std::size_t j = std::size_t(s.neighbours[std::size_t(k)]);
        const double rsum = ri + fit.radius[std::size_t(s.species[j])];
        in_contact = s.id[j] == partner && distance(i, j) < rsum + tol;
      }
      if (!in_contact)
        fail(fmt::format("{} = {} is not a neighbour in contact with particle {}",
                         at("/state/history_partner", i * slots + a), partner, s.id[i]));
    }
    bool on_obstacle = false;
    if (fit.obstacle_distance) {
      on_obstacle = fit.obstacle_distance(&s.position[i * dim]) < ri + tol;
    }
    if (!on_obstacle && !s.history_obstacle_spring.empty() &&
        norm(s.history_obstacle_spring, i * dim, dim) != 0)
      fail(fmt::format("{} is not zero, but particle {} does not touch the obstacle",
                       at("/state/history_obstacle_spring", i * dim), s.id[i]));
    if (contacts > 0 || on_obstacle) continue;
    if (norm(s.force, i * dim, dim) != 0)
      fail(fmt::format("{} is not zero, but particle {} touches nothing",
                       at("/state/force", i * dim), s.id[i]));
    const std::size_t spins = std::size_t(spin_components(s.dim));
    if (slots > 0 && norm(s.torque, i * spins, spins) != 0)
      fail(fmt::format("{} = {}, but particle {} touches nothing", at("/state/torque", i * spins),
                       s.torque[i * spins], s.id[i]));
  }
}

}  // namespace granshock

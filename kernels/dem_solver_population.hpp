// Insertion and per-species moments of a DemSolver. Included by dem_solver.hpp.
#pragma once

#include <cmath>

namespace granshock {

// Inserts particles in a rectangle without overlaps, entirely on the device, in rounds
// (docs/scene_format.md, "The inflow"). One round:
//  1. draw 2R + 32 candidate positions from the counter RNG (R still wanted);
//  2. reject a candidate that overlaps a particle already near the region (including
//     those placed by earlier rounds), or any candidate of this round with a smaller
//     index (conservative, order-independent, so the choice is the same on every
//     backend);
//  3. keep the first survivors, in candidate order, with consecutive ids.
// One round alone is a Matern type-II hard-core process, which cannot exceed an area
// fraction of 1/4 for equal discs; further rounds fill the gaps it leaves, towards the
// random-sequential-adsorption limit. Rounds stop when the request is met, when a round
// places nothing, or after kInsertionRounds. The first round is all a dilute inflow
// needs, so later rounds change nothing there.
// Candidates use the largest diameter of the scene, so no species can overlap; none is
// placed within one diameter of the obstacle.
template <class Traits, class ExecSpace>
int DemSolver<Traits, ExecSpace>::insert(const InsertionRequest& rq) {
  if (rq.count <= 0) return 0;
  if (int(rq.number_fraction.size()) != int(setup_.species.size()))
    throw std::invalid_argument("insert: one number fraction per species is required");
  if (p_.n + rq.count > p_.capacity()) grow(p_.n + rq.count + p_.capacity() / 4);
  const int n_before = p_.n;
  long first_candidate = 0;
  for (int round = 0; round < kInsertionRounds && p_.n - n_before < rq.count; ++round) {
    const int wanted = rq.count - (p_.n - n_before);
    const int m = 2 * wanted + 32;
    const int placed = insert_round(rq, p_.n - n_before, wanted, m, first_candidate);
    first_candidate += m;
    p_.n += placed;
    if (placed == 0) break;
  }
  const int take = p_.n - n_before;
  next_id_ += take;
  if (rq.rebuild_lists) rebuild_lists();
  return take;
}

// One round of insert(): places up to `wanted` particles after the `placed` ones of
// earlier rounds, drawing candidates first_candidate .. first_candidate + m - 1 of the
// event's stream. Returns how many it placed at [p_.n, p_.n + placed).
template <class Traits, class ExecSpace>
int DemSolver<Traits, ExecSpace>::insert_round(const InsertionRequest& rq, int placed, int wanted,
                                               int m, long first_candidate) {
  const int n_species = int(setup_.species.size());
  const int n = p_.n;
  const Real dmax = Real(setup_.max_diameter());
  const Real x0 = Real(rq.x_range[0]), y0 = Real(rq.y_range[0]);
  const Real wx = Real(rq.x_range[1] - rq.x_range[0]), wy = Real(rq.y_range[1] - rq.y_range[0]);
  const auto box = box_;
  const auto x = p_.x;

  // Particles that could touch a candidate: those within one diameter of the region.
  Kokkos::View<int*, Mem> near("insert_near", n > 0 ? n : 1);
  int n_near = 0;
  Kokkos::parallel_scan(
      "insert::near", Policy(0, n),
      KOKKOS_LAMBDA(const int i, int& running, const bool final) {
        const bool close = x(i, 1) > y0 - dmax && x(i, 1) < y0 + wy + dmax;
        if (final && close) near(running) = i;
        running += close ? 1 : 0;
      },
      n_near);

  const CounterRng rng{rq.seed};
  const std::uint64_t pos_stream = InsertionStreams::position(rq.event);
  Kokkos::View<Real* [2], Mem> cand("insert_candidates", m);
  Kokkos::parallel_for(
      "insert::draw", Policy(0, m), KOKKOS_LAMBDA(const int k) {
        const std::uint64_t c = std::uint64_t(first_candidate + k);
        cand(k, 0) = x0 + Real(rng.uniform(pos_stream, 2 * c)) * wx;
        cand(k, 1) = y0 + Real(rng.uniform(pos_stream, 2 * c + 1)) * wy;
      });
  const auto cyl = cylinder_;
  Kokkos::View<int*, Mem> rank("insert_rank", m);
  int accepted = 0;
  const Real d2 = dmax * dmax;
  Kokkos::parallel_scan(
      "insert::accept", Policy(0, m),
      KOKKOS_LAMBDA(const int k, int& running, const bool final) {
        capture_before_if_constexpr(cyl, dmax);
        bool ok = true;
        Vec<Dim, Real> ck = Vec<Dim, Real>::zero();
        ck[0] = cand(k, 0);
        ck[1] = cand(k, 1);
        if constexpr (Traits::obstacle) {  // never inside or touching the obstacle
          const Real cx = ck[0] - cyl.centre[0], cy = ck[1] - cyl.centre[1];
          const Real reach = cyl.radius + dmax;
          ok = cx * cx + cy * cy >= reach * reach;
        }
        for (int e = 0; e < n_near && ok; ++e) {
          Vec<Dim, Real> dx;
          for (int d = 0; d < Dim; ++d) dx[d] = ck[d] - x(near(e), d);
          dx = box.minimum_image(dx);
          ok = dot(dx, dx) >= d2;
        }
        for (int j = 0; j < k && ok; ++j) {
          Vec<Dim, Real> dx = Vec<Dim, Real>::zero();
          dx[0] = ck[0] - cand(j, 0);
          dx[1] = ck[1] - cand(j, 1);
          dx = box.minimum_image(dx);
          ok = dot(dx, dx) >= d2;
        }
        if (final) rank(k) = ok ? running : -1;
        running += ok ? 1 : 0;
      },
      accepted);
  const int take = accepted < wanted ? accepted : wanted;

  Kokkos::View<double*, Mem> cumulative("insert_cumulative", n_species);
  {
    auto h = Kokkos::create_mirror_view(cumulative);
    double c = 0;
    for (int s = 0; s < n_species; ++s) h(s) = (c += rq.number_fraction[s]);
    Kokkos::deep_copy(cumulative, h);
  }
  const std::uint64_t vel_stream = InsertionStreams::velocity(rq.event);
  const Real ux = Real(rq.mean_velocity[0]), uy = Real(rq.mean_velocity[1]);
  const double sigma = rq.sigma_m_per_s;
  const long first = rq.inserted_before + placed;
  const int first_id = next_id_ + placed;
  const auto v = p_.v, f = p_.f, xref = x_ref_;
  const auto species = p_.species, id = p_.id;
  const auto omega = p_.omega, torque = p_.torque;
  const auto history = history_;
  Kokkos::parallel_for(
      "insert::place", Policy(0, m), KOKKOS_LAMBDA(const int k) {
        capture_before_if_constexpr(omega, torque, history);
        const int r = rank(k);
        if (r < 0 || r >= take) return;
        const int i = n + r;
        const std::uint64_t q = std::uint64_t(placed + r);  // rank within the whole event
        for (int d = 0; d < Dim; ++d) {
          x(i, d) = d < 2 ? cand(k, d) : Real(0);
          f(i, d) = 0;
        }
        v(i, 0) = ux + Real(sigma * rng.normal(vel_stream, 2 * q));
        v(i, 1) = uy + Real(sigma * rng.normal(vel_stream, 2 * q + 1));
        for (int d = 2; d < Dim; ++d) v(i, d) = 0;
        for (int d = 0; d < Dim; ++d) xref(i, d) = x(i, d);
        species(i) = species_for(cumulative, first + r);
        id(i) = first_id + r;
        if constexpr (Traits::friction) {
          omega(i) = 0;
          torque(i) = 0;
          // A new particle has no contacts: free slots with zero springs, as the force
          // kernel keeps them (the row may hold a deleted particle's history).
          for (int s = 0; s < ContactHistory<Dim, Real, Mem>::slots; ++s) {
            history.partner(i, s) = -1;
            for (int d = 0; d < Dim; ++d) history.spring(i, Dim * s + d) = 0;
          }
          for (int d = 0; d < Dim; ++d) history.wall_spring(i, d) = 0;
        }
      });
  return take;
}

template <class Traits, class ExecSpace>
std::vector<SpeciesMoments> DemSolver<Traits, ExecSpace>::species_moments() const {
  const auto v = p_.v;
  const auto species = p_.species;
  std::vector<SpeciesMoments> out(setup_.species.size());
  for (int s = 0; s < int(out.size()); ++s) {
    double count = 0;
    Kokkos::parallel_reduce(
        "moments::count", Policy(0, p_.n),
        KOKKOS_LAMBDA(const int i, double& acc) { acc += species(i) == s ? 1.0 : 0.0; }, count);
    out[s].count = long(count);
    for (int c = 0; c < Dim; ++c) {
      Kokkos::parallel_reduce(
          "moments::velocity", Policy(0, p_.n),
          KOKKOS_LAMBDA(const int i, double& acc) {
            acc += species(i) == s ? double(v(i, c)) : 0.0;
          },
          out[s].velocity_sum[c]);
    }
    Kokkos::parallel_reduce(
        "moments::speed2", Policy(0, p_.n),
        KOKKOS_LAMBDA(const int i, double& acc) {
          if (species(i) != s) return;
          for (int c = 0; c < Dim; ++c) acc += double(v(i, c)) * double(v(i, c));
        },
        out[s].speed_squared_sum);
  }
  return out;
}

}  // namespace granshock

// Which particles exist (docs/design.md, "Particles"): insertion of new particles in a
// region without overlaps, deletion of those that left through an open face, the global
// ids and the deletion counts. Both keep the arrays' capacity, so no allocation happens
// in steady state; only an insertion past the capacity grows the store.
#pragma once

#include <Kokkos_Core.hpp>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/communicator.hpp"
#include "core/solver.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/device/box_geometry.hpp"
#include "kernels/device/counter_rng.hpp"
#include "kernels/device/device_lambda.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/population_kernels.hpp"
#include "kernels/particles/variant_types.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
class ParticlePopulation {
 public:
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Mem = typename Types::Mem;
  using Policy = typename Types::Policy;
  using Store = typename Types::Store;
  using Obstacle = typename Types::Obstacle;
  // Candidates, the overlap test and the escape test are in Position (double) in every
  // variant (device/position.hpp).
  using Position = typename Types::Position;
  static constexpr int kInsertionRounds = 16;

  ParticlePopulation() = default;
  ParticlePopulation(const SolverSetup& setup, const BoxGeometry<Dim, Position>& box,
                     const Obstacle& obstacle)
      : box_(box),
        obstacle_(obstacle),
        max_diameter_(Real(setup.max_diameter())),
        cumulative_("insert_cumulative", setup.species.size()) {
    for (int d = 0; d < Dim; ++d) {
      escape_.lo[d] = Position(setup.box.lo[d]);
      escape_.hi[d] = Position(setup.box.hi[d]);
      escape_.check[d] = setup.delete_outside && !setup.box.periodic[d];
      deletes_ = deletes_ || escape_.check[d];
    }
  }

  // Inserts particles in a rectangle (in 3-D a box: x_range x y_range x z_range, z and the
  // z velocity drawn from streams of their own) without overlaps, entirely on the device,
  // in rounds (docs/scene_format.md, "The inflow"). One round:
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
  // needs, so later rounds change nothing there. Candidates use the largest diameter of
  // the scene, so no species can overlap; the obstacle keeps them one diameter away.
  // Returns how many were placed (at the end of the store).
  // Several processes (`everyone`): each tests the candidates against the particles near
  // the region on every rank (gathered), so every rank places the same particles, and
  // keeps those of its slab afterwards (SlabExchange::keep_own).
  int insert(Store& p, const InsertionRequest& rq, const Communicator* everyone = nullptr) {
    if (rq.count <= 0) return 0;
    if (rq.number_fraction.size() != cumulative_.extent(0))
      throw std::invalid_argument("insert: one number fraction per species is required");
    if (p.n + rq.count > p.capacity()) grow(p, p.n + rq.count + p.capacity() / 4);
    set_number_fractions(rq.number_fraction);
    const int n_before = p.n;
    long first_candidate = 0;
    for (int round = 0; round < kInsertionRounds && p.n - n_before < rq.count; ++round) {
      const int wanted = rq.count - (p.n - n_before);
      const int m = 2 * wanted + 32;
      const int placed = insert_round(p, rq, p.n - n_before, wanted, m, first_candidate, everyone);
      first_candidate += m;
      p.n += placed;
      if (placed == 0) break;
    }
    const int take = p.n - n_before;
    next_id_ += take;
    return take;
  }

  // One round of insert(): places up to `wanted` particles after the `placed` ones of
  // earlier rounds, drawing candidates first_candidate .. first_candidate + m - 1 of the
  // event's stream. Returns how many it placed at [p.n, p.n + placed). Public because it
  // launches KOKKOS_LAMBDAs (nvcc).
  int insert_round(const Store& p, const InsertionRequest& rq, int placed, int wanted, int m,
                   long first_candidate, const Communicator* everyone) {
    const int n = p.n;
    const Real dmax = max_diameter_;
    const Position x0 = Position(rq.x_range[0]), y0 = Position(rq.y_range[0]);
    const Position wx = Position(rq.x_range[1] - rq.x_range[0]);
    const Position wy = Position(rq.y_range[1] - rq.y_range[0]);
    const Position z0 = Position(rq.z_range[0]), wz = Position(rq.z_range[1] - rq.z_range[0]);
    const auto box = box_;
    const auto x = p.x;

    // Particles that could touch a candidate: those within one diameter of the region.
    // The test below is a logical and over them, so their order does not matter.
    Kokkos::View<Position* [Dim], Mem> near("insert_near", n > 0 ? n : 1);
    int n_near = 0;
    Kokkos::parallel_scan(
        "insert::near", Policy(0, n),
        KOKKOS_LAMBDA(const int i, int& running, const bool final) {
          const bool close = x(i, 1) > y0 - dmax && x(i, 1) < y0 + wy + dmax;
          if (final && close)
            for (int d = 0; d < Dim; ++d) near(running, d) = x(i, d);
          running += close ? 1 : 0;
        },
        n_near);
    if (everyone != nullptr && everyone->size() > 1) near = gathered(near, n_near, *everyone);

    const CounterRng rng{rq.seed};
    const std::uint64_t pos_stream = InsertionStreams::position(rq.event);
    const std::uint64_t depth_stream = InsertionStreams::depth_position(rq.event);
    Kokkos::View<Position* [Dim], Mem> cand("insert_candidates", m);
    Kokkos::parallel_for(
        "insert::draw", Policy(0, m), KOKKOS_LAMBDA(const int k) {
          const std::uint64_t c = std::uint64_t(first_candidate + k);
          cand(k, 0) = x0 + Position(rng.uniform(pos_stream, 2 * c)) * wx;
          cand(k, 1) = y0 + Position(rng.uniform(pos_stream, 2 * c + 1)) * wy;
          for (int d = 2; d < Dim; ++d)
            cand(k, d) = z0 + Position(rng.uniform(depth_stream, c)) * wz;
        });
    const auto obstacle = obstacle_;
    Kokkos::View<int*, Mem> rank("insert_rank", m);
    int accepted = 0;
    const Position d2 = Position(dmax) * Position(dmax);
    Kokkos::parallel_scan(
        "insert::accept", Policy(0, m),
        KOKKOS_LAMBDA(const int k, int& running, const bool final) {
          Vec<Dim, Position> ck;
          for (int d = 0; d < Dim; ++d) ck[d] = cand(k, d);
          bool ok = !obstacle.keeps_out(ck[0], ck[1], dmax);
          for (int e = 0; e < n_near && ok; ++e) {
            Vec<Dim, Position> dx;
            for (int d = 0; d < Dim; ++d) dx[d] = ck[d] - near(e, d);
            dx = box.minimum_image(dx);
            ok = dot(dx, dx) >= d2;
          }
          for (int j = 0; j < k && ok; ++j) {
            Vec<Dim, Position> dx;
            for (int d = 0; d < Dim; ++d) dx[d] = ck[d] - cand(j, d);
            dx = box.minimum_image(dx);
            ok = dot(dx, dx) >= d2;
          }
          if (final) rank(k) = ok ? running : -1;
          running += ok ? 1 : 0;
        },
        accepted);
    const int take = accepted < wanted ? accepted : wanted;

    const std::uint64_t vel_stream = InsertionStreams::velocity(rq.event);
    const std::uint64_t depth_vel_stream = InsertionStreams::depth_velocity(rq.event);
    const Real ux = Real(rq.mean_velocity[0]), uy = Real(rq.mean_velocity[1]);
    const double sigma = rq.sigma_m_per_s;
    const long first = rq.inserted_before + placed;
    const int first_id = next_id_ + placed;
    const auto cumulative = cumulative_;
    const Store q = p;
    Kokkos::parallel_for(
        "insert::place", Policy(0, m), KOKKOS_LAMBDA(const int k) {
          const int r = rank(k);
          if (r < 0 || r >= take) return;
          const int i = n + r;
          const std::uint64_t s = std::uint64_t(placed + r);  // rank within the whole event
          for (int d = 0; d < Dim; ++d) {
            q.x(i, d) = cand(k, d);
            q.f(i, d) = 0;
          }
          q.v(i, 0) = ux + Real(sigma * rng.normal(vel_stream, 2 * s));
          q.v(i, 1) = uy + Real(sigma * rng.normal(vel_stream, 2 * s + 1));
          for (int d = 2; d < Dim; ++d) q.v(i, d) = Real(sigma * rng.normal(depth_vel_stream, s));
          for (int d = 0; d < Dim; ++d) q.x_ref(i, d) = q.x(i, d);
          q.species(i) = species_for(cumulative, first + r);
          q.id(i) = first_id + r;
          // It touched nothing in the last force pass (placed without overlaps): no contact
          // virial for a sample before the next one (docs/fields.md, "The contact virial").
          for (int c = 0; c < Dim * Dim; ++c) q.virial(i, c) = 0;
          if constexpr (V::friction) {
            store_spin<Dim>(q.omega, i, zero_spin<Dim, Real>());
            store_spin<Dim>(q.torque, i, zero_spin<Dim, Real>());
            // The row may hold a deleted particle's history: free every slot and zero
            // its spring, as the force kernel keeps them.
            for (int slot = 0; slot < Store::history_slots; ++slot) {
              q.history_partner(i, slot) = -1;
              for (int d = 0; d < Dim; ++d) q.history_spring(i, Dim * slot + d) = 0;
            }
            for (int d = 0; d < Dim; ++d) q.obstacle_spring(i, d) = 0;
          }
        });
    return take;
  }

  // The first `count` rows of every rank's `near`, concatenated; count becomes the total.
  static Kokkos::View<Position* [Dim], Mem> gathered(const Kokkos::View<Position* [Dim], Mem>& near,
                                                     int& count, const Communicator& everyone) {
    const auto mine = host_copy<Paths>(near);
    std::vector<char> bytes(sizeof(Position) * Dim * std::size_t(count));
    for (int e = 0; e < count; ++e)
      for (int d = 0; d < Dim; ++d) {
        const Position value = mine(e, d);
        std::memcpy(bytes.data() + sizeof(Position) * (std::size_t(e) * Dim + d), &value,
                    sizeof value);
      }
    const std::vector<char> all = everyone.all_gather(bytes);
    count = int(all.size() / (sizeof(Position) * Dim));
    Kokkos::View<Position* [Dim], Mem> out("insert_near_all", count > 0 ? count : 1);
    auto host = host_mirror<Paths>(out);
    for (int e = 0; e < count; ++e)
      for (int d = 0; d < Dim; ++d)
        std::memcpy(&host(e, d), all.data() + sizeof(Position) * (std::size_t(e) * Dim + d),
                    sizeof(Position));
    Kokkos::deep_copy(out, host);
    return out;
  }

  // Deletes the particles beyond an open face (a stable compaction through `permute`),
  // counting them per face. Called at every neighbour-list rebuild.
  template <class Permutation>
  void remove_escaped(Store& p, Permutation& permute) {
    if (!deletes_) return;
    if (int(keep_order_.extent(0)) < p.capacity())
      keep_order_ = Kokkos::View<int*, Mem>("keep_order", p.capacity());
    long per_face[2 * Dim];
    const int kept =
        compact_escaped<Dim, Position, ExecSpace>(escape_, p.x, p.n, keep_order_, per_face);
    if (kept == p.n) return;
    for (int d = 0; d < Dim; ++d) {
      removed_.low[d] += per_face[2 * d];
      removed_.high[d] += per_face[2 * d + 1];
    }
    permute.apply(p, keep_order_, kept);
    p.n = kept;
  }

  // Grows the arrays to `capacity`, keeping the n owned particles (rare: only when an
  // insertion needs more room than the scene's estimate).
  static void grow(Store& p, int capacity) {
    Store bigger;
    bigger.allocate(capacity);
    copy_particles<ExecSpace>(bigger, p, p.n);
    p = bigger;
  }

  const EscapeTest<Dim, Position>& escape_test() const { return escape_; }
  const RemovalCounts& removed() const { return removed_; }
  int next_id() const { return next_id_; }
  void restore(int next_id, const RemovalCounts& removed) {
    next_id_ = next_id;
    removed_ = removed;
  }

 private:
  void set_number_fractions(const std::vector<double>& fractions) {
    auto h = host_mirror<Paths>(cumulative_);
    double c = 0;
    for (std::size_t s = 0; s < fractions.size(); ++s) h(s) = (c += fractions[s]);
    Kokkos::deep_copy(cumulative_, h);
  }

  BoxGeometry<Dim, Position> box_{};
  Obstacle obstacle_{};
  Real max_diameter_ = 0;
  Kokkos::View<double*, Mem> cumulative_;  // cumulative number fractions per species
  EscapeTest<Dim, Position> escape_{};
  bool deletes_ = false;
  Kokkos::View<int*, Mem> keep_order_;
  RemovalCounts removed_;
  int next_id_ = 0;
};

}  // namespace granshock

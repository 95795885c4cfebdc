// What a solver reports about its particles (docs/design.md, "The solver"): energies,
// momentum, contacts and non-finite states as device reductions, the moments of each
// species, and the list of touching pairs (host, for tests). Contacts and elastic energy
// go through the pair loop and the obstacle's shape, so they use the same criterion as
// the force kernel. Every sum is local to the process and completed by the Communicator.
#pragma once

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <utility>
#include <vector>

#include "core/communicator.hpp"
#include "core/solver.hpp"
#include "kernels/device/backends.hpp"
#include "kernels/device/device_lambda.hpp"
#include "kernels/device/host_mirror.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/neighbours/pair_loop.hpp"
#include "kernels/particles/particle_store.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/solver/pair_table.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths = DefaultPaths<ExecSpace>>
struct SolverDiagnostics {
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Model = typename Types::Model;
  using Mem = typename Types::Mem;
  using Policy = typename Types::Policy;
  using Store = typename Types::Store;
  using Table = PairTable<Model, Real, Mem>;
  using Obstacle = typename Types::Obstacle;
  using Position = typename Types::Position;  // of x: double (device/position.hpp)

  Store p;
  PairLoop<Dim, Real, Mem> pairs;
  Table table;
  Obstacle obstacle;

  template <class Body>
  double sum(const char* label, const Body& body) const {
    double total = 0;
    Kokkos::parallel_reduce(label, Policy(0, p.n), body, total);
    return total;
  }

  Diagnostics compute(const Communicator& comm) const {
    const auto x = p.x;  // one type per auto declaration: PositionView
    const auto v = p.v;  // VectorView
    const auto omega = p.omega;
    const auto species = p.species, id = p.id;
    const auto table_ = table;
    const auto pairs_ = pairs;
    const auto obstacle_ = obstacle;
    Diagnostics out;
    out.non_finite = long(sum(
        "diag::non_finite", KOKKOS_LAMBDA(const int i, double& acc) {
          bool ok = true;
          for (int d = 0; d < Dim; ++d)
            ok = ok && dmath::is_finite(double(x(i, d))) && dmath::is_finite(double(v(i, d)));
          acc += ok ? 0.0 : 1.0;
        }));
    out.kinetic_energy = sum(
        "diag::kinetic", KOKKOS_LAMBDA(const int i, double& acc) {
          double v2 = 0;
          for (int d = 0; d < Dim; ++d) v2 += double(v(i, d)) * double(v(i, d));
          acc += 0.5 * v2 / double(table_.inv_mass(species(i)));
        });
    if constexpr (V::friction) {
      out.rotational_energy = sum(
          "diag::rotational", KOKKOS_LAMBDA(const int i, double& acc) {
            acc += 0.5 * spin_square<Dim>(omega, i) / double(table_.inv_inertia(species(i)));
          });
    }
    for (int c = 0; c < Dim; ++c) {
      out.momentum[c] = sum(
          "diag::momentum", KOKKOS_LAMBDA(const int i, double& acc) {
            acc += double(v(i, c)) / double(table_.inv_mass(species(i)));
          });
    }
    // Each touching pair appears twice in the full list: give each appearance half of the
    // pair's elastic energy, and count the pair once (from the smaller id).
    out.elastic_energy = sum(
        "diag::elastic", KOKKOS_LAMBDA(const int i, double& acc) {
          const int si = species(i);
          const Vec<Dim, Position> xi = pairs_.position(i);
          const Real ri = table_.radius(si);
          pairs_.for_each_contact(i, xi,
                                  [&](int, int sj, const Vec<Dim, Real>&, Real r2, Real rsum) {
                                    const double dn = double(rsum) - dmath::sqrt(double(r2));
                                    acc += 0.5 * Model::elastic_energy(table_.pair(si, sj), dn);
                                  });
          Real dn;
          Vec<Dim, Real> n;
          if (obstacle_.touches(xi, ri, dn, n))
            acc += Model::elastic_energy(table_.obstacle(si), double(dn));
        });
    out.contacts = long(sum(
        "diag::contacts", KOKKOS_LAMBDA(const int i, double& acc) {
          const int si = species(i);
          const Vec<Dim, Position> xi = pairs_.position(i);
          const Real ri = table_.radius(si);
          pairs_.for_each_contact(i, xi, [&](int j, int, const Vec<Dim, Real>&, Real, Real) {
            if (id(j) > id(i)) acc += 1;
          });
          Real dn;
          Vec<Dim, Real> n;
          if (obstacle_.touches(xi, ri, dn, n)) acc += 1;
        }));
    out.inside_obstacle = long(sum(
        "diag::inside_obstacle", KOKKOS_LAMBDA(const int i, double& acc) {
          Vec<Dim, Position> xi;
          for (int d = 0; d < Dim; ++d) xi[d] = x(i, d);
          acc += obstacle_.contains(xi) ? 1.0 : 0.0;
        }));
    out.kinetic_energy = comm.sum(out.kinetic_energy);
    out.rotational_energy = comm.sum(out.rotational_energy);
    out.elastic_energy = comm.sum(out.elastic_energy);
    out.contacts = comm.sum(out.contacts);
    out.non_finite = comm.sum(out.non_finite);
    out.inside_obstacle = comm.sum(out.inside_obstacle);
    for (double& m : out.momentum) m = comm.sum(m);
    return out;
  }

  std::vector<SpeciesMoments> species_moments(int n_species, const Communicator& comm) const {
    const auto v = p.v;
    const auto species = p.species;
    std::vector<SpeciesMoments> out(static_cast<std::size_t>(n_species));
    for (int s = 0; s < n_species; ++s) {
      SpeciesMoments& m = out[std::size_t(s)];
      m.count = comm.sum(long(sum(
          "moments::count",
          KOKKOS_LAMBDA(const int i, double& acc) { acc += species(i) == s ? 1.0 : 0.0; })));
      for (int c = 0; c < Dim; ++c)
        m.velocity_sum[c] = comm.sum(sum(
            "moments::velocity", KOKKOS_LAMBDA(const int i, double& acc) {
              acc += species(i) == s ? double(v(i, c)) : 0.0;
            }));
      m.speed_squared_sum = comm.sum(sum(
          "moments::speed2", KOKKOS_LAMBDA(const int i, double& acc) {
            if (species(i) != s) return;
            for (int c = 0; c < Dim; ++c) acc += double(v(i, c)) * double(v(i, c));
          }));
    }
    return out;
  }

  // Touching particle pairs as (smaller global id, larger global id), sorted (for tests):
  // counted, then listed, by the pair loop on the device.
  std::vector<std::pair<int, int>> contact_pairs() const {
    const auto id = p.id;
    const auto pairs_ = pairs;
    Kokkos::View<int*, Mem> offsets("pair_offsets", p.n + 1);
    Kokkos::parallel_for(
        "diag::count_pairs", Policy(0, p.n), KOKKOS_LAMBDA(const int i) {
          int count = 0;
          pairs_.for_each_contact(i, pairs_.position(i),
                                  [&](int j, int, const Vec<Dim, Real>&, Real, Real) {
                                    if (id(j) > id(i)) ++count;
                                  });
          offsets(i + 1) = count;
        });
    int total = 0;
    Kokkos::parallel_scan(
        "diag::pair_offsets", Policy(0, p.n + 1),
        KOKKOS_LAMBDA(const int i, int& running, const bool final) {
          running += i == 0 ? 0 : offsets(i);
          if (final) offsets(i) = running;
        },
        total);
    Kokkos::View<int* [2], Mem> list("pair_list", total);
    Kokkos::parallel_for(
        "diag::list_pairs", Policy(0, p.n), KOKKOS_LAMBDA(const int i) {
          int k = offsets(i);
          pairs_.for_each_contact(i, pairs_.position(i),
                                  [&](int j, int, const Vec<Dim, Real>&, Real, Real) {
                                    if (id(j) <= id(i)) return;
                                    list(k, 0) = id(i);
                                    list(k, 1) = id(j);
                                    ++k;
                                  });
        });
    const auto host = host_copy<Paths>(list);
    std::vector<std::pair<int, int>> out;
    for (int k = 0; k < total; ++k) out.emplace_back(host(k, 0), host(k, 1));
    std::sort(out.begin(), out.end());
    return out;
  }
};

}  // namespace granshock

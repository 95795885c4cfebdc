// Diagnostics of a DemSolver: energies, momentum and contacts (device reductions), and
// the list of touching pairs (host, for tests). Included by dem_solver.hpp.
#pragma once

#include <algorithm>

#include "device_lambda.hpp"

namespace granshock {

template <class Traits, class ExecSpace>
Diagnostics DemSolver<Traits, ExecSpace>::diagnostics() const {
  const auto x = p_.x, v = p_.v;  // one type per auto declaration (VectorView)
  const auto omega = p_.omega;
  const auto species = p_.species, id = p_.id;
  const auto off = list_.offsets, nb = list_.neighbours;
  const auto table = table_;
  const auto box = box_;
  const auto cyl = cylinder_;
  const int n = p_.n;

  auto sum = [&](const char* label, auto&& body) {
    double total = 0;
    Kokkos::parallel_reduce(label, Policy(0, n), body, total);
    return total;
  };
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
        acc += 0.5 * v2 / double(table.inv_mass(species(i)));
      });
  if constexpr (Traits::friction) {
    out.rotational_energy = sum(
        "diag::rotational", KOKKOS_LAMBDA(const int i, double& acc) {
          acc += 0.5 * double(omega(i)) * double(omega(i)) / double(table.inv_inertia(species(i)));
        });
  }
  for (int c = 0; c < Dim; ++c) {
    out.momentum[c] = sum(
        "diag::momentum", KOKKOS_LAMBDA(const int i, double& acc) {
          acc += double(v(i, c)) / double(table.inv_mass(species(i)));
        });
  }
  // Each touching pair appears twice in the full list: count it once (smaller id first),
  // and give each appearance half of the pair's elastic energy.
  out.elastic_energy = sum(
      "diag::elastic", KOKKOS_LAMBDA(const int i, double& acc) {
        capture_before_if_constexpr(cyl);
        const int si = species(i);
        for (int k = off(i); k < off(i + 1); ++k) {
          const int j = nb(k);
          Vec<Dim, Real> dx;
          for (int d = 0; d < Dim; ++d) dx[d] = x(i, d) - x(j, d);
          dx = box.minimum_image(dx);
          const double dn = double(table.radius(si) + table.radius(species(j))) -
                            dmath::sqrt(double(dot(dx, dx)));
          if (dn > 0)
            acc += 0.5 * double(table.pair(si, species(j)).energy_coef) * dn * dn * dmath::sqrt(dn);
        }
        if constexpr (Traits::obstacle) {
          double r2 = 0;
          for (int d = 0; d < 2; ++d)
            r2 += double(x(i, d) - cyl.centre[d]) * double(x(i, d) - cyl.centre[d]);
          const double dn = double(table.radius(si) + cyl.radius) - dmath::sqrt(r2);
          if (dn > 0) acc += double(table.wall(si).energy_coef) * dn * dn * dmath::sqrt(dn);
        }
      });
  out.contacts = long(sum(
      "diag::contacts", KOKKOS_LAMBDA(const int i, double& acc) {
        capture_before_if_constexpr(cyl);
        const int si = species(i);
        for (int k = off(i); k < off(i + 1); ++k) {
          const int j = nb(k);
          if (id(j) < id(i)) continue;
          Vec<Dim, Real> dx;
          for (int d = 0; d < Dim; ++d) dx[d] = x(i, d) - x(j, d);
          dx = box.minimum_image(dx);
          const Real reach = table.radius(si) + table.radius(species(j));
          if (dot(dx, dx) < reach * reach) acc += 1;
        }
        if constexpr (Traits::obstacle) {
          Real r2 = 0;
          for (int d = 0; d < 2; ++d) r2 += (x(i, d) - cyl.centre[d]) * (x(i, d) - cyl.centre[d]);
          const Real reach = table.radius(si) + cyl.radius;
          if (r2 < reach * reach) acc += 1;
        }
      }));
  return out;
}

template <class Traits, class ExecSpace>
std::vector<std::pair<int, int>> DemSolver<Traits, ExecSpace>::contact_pairs() const {
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.x);
  const auto species = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.species);
  const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p_.id);
  const auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list_.offsets);
  const auto nb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list_.neighbours);
  const auto radius = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), table_.radius);
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < p_.n; ++i) {
    for (int k = off(i); k < off(i + 1); ++k) {
      const int j = nb(k);
      if (id(j) < id(i)) continue;
      Vec<Dim, Real> dx;
      for (int d = 0; d < Dim; ++d) dx[d] = x(i, d) - x(j, d);
      dx = box_.minimum_image(dx);
      const Real reach = radius(species(i)) + radius(species(j));
      if (dot(dx, dx) < reach * reach) pairs.emplace_back(id(i), id(j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace granshock

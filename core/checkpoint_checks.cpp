// The checks that need nothing but the checkpoint itself.
#include <algorithm>
#include <climits>
#include <cmath>

#include "core/checkpoint_check_support.hpp"

namespace granshock {

using namespace checks;

UserError refuse_checkpoint(const std::filesystem::path& file, const InvalidCheckpoint& e) {
  return UserError(
      fmt::format("checkpoint '{}' is invalid: {}; it cannot be resumed; rerun with "
                  "--overwrite",
                  file.string(), e.what()));
}

namespace {

void check_counters(const SolverState& s) {
  if (s.dim != 2 && s.dim != 3) fail(fmt::format("/state@dim = {} is not 2 or 3", s.dim));
  if (s.step < 0) fail(fmt::format("/state@step = {} is negative", s.step));
  if (s.next_id < 0) fail(fmt::format("/state@next_id = {} is negative", s.next_id));
  // An upper bound only against overflow in n * slots * dim; solvers have 8 or 16.
  if (s.history_slots < 0 || s.history_slots > 64)
    fail(fmt::format("/state@history_slots = {} is not in [0, 64]", s.history_slots));
  if (s.list_builds < 0) fail(fmt::format("/state@list_builds = {} is negative", s.list_builds));
  if (!(s.skin >= 0 && std::isfinite(s.skin)))
    fail(fmt::format("/state@skin = {} is not a length >= 0", s.skin));
  if (s.last_build_step < 0 || s.last_build_step > s.step)
    fail(fmt::format("/state@last_build_step = {} is not in [0, step = {}]", s.last_build_step,
                     s.step));
  for (int d = 0; d < 3; ++d) {
    if (s.removed_low[d] < 0) fail(fmt::format("/state@removed_low[{}] is negative", d));
    if (s.removed_high[d] < 0) fail(fmt::format("/state@removed_high[{}] is negative", d));
  }
  if (s.size() > std::size_t(INT_MAX)) fail("/state/id has more particles than a solver can hold");
}

void check_shapes(const SolverState& s) {
  const std::size_t n = s.size(), dim = std::size_t(s.dim), slots = std::size_t(s.history_slots);
  const std::string rows = fmt::format("n = {} particles (/state/id) of dim {}", n, dim);
  expect_size("/state/position", s.position, n * dim, rows);
  expect_size("/state/velocity", s.velocity, n * dim, rows);
  expect_size("/state/force", s.force, n * dim, rows);
  expect_size("/state/reference_position", s.reference_position, n * dim, rows);
  expect_size("/state/species", s.species, n, rows);
  const bool friction = slots > 0;
  const std::string slot_rows = friction ? fmt::format("{} and {} history slots", rows, slots)
                                         : "no contact history without friction (slots = 0)";
  const std::size_t spins = friction ? n * std::size_t(spin_components(s.dim)) : 0;
  expect_size("/state/angular_velocity", s.angular_velocity, spins, slot_rows);
  expect_size("/state/torque", s.torque, spins, slot_rows);
  expect_size("/state/history_partner", s.history_partner, n * slots, slot_rows);
  expect_size("/state/history_spring", s.history_spring, n * slots * dim, slot_rows);
  // The wall springs may be stored empty (docs/output_format.md); the solver decides.
  if (!(friction && s.history_obstacle_spring.empty()))
    expect_size("/state/history_obstacle_spring", s.history_obstacle_spring, friction ? n * dim : 0,
                slot_rows);
  // May be absent (a solver that held none, or a format-3 file written before it was kept:
  // docs/output_format.md, "Checkpoint format versions").
  if (!s.contact_virial.empty())
    expect_size("/state/contact_virial", s.contact_virial, n * dim * dim, rows);
}

void check_neighbours(const SolverState& s) {
  const std::size_t n = s.size();
  const std::vector<int>& offsets = s.neighbour_offsets;
  if (offsets.empty() && n == 0 && s.neighbours.empty()) return;  // never built
  expect_size("/state/neighbour_offsets", offsets, n + 1, fmt::format("n + 1 for n = {}", n));
  if (offsets[0] != 0) fail(fmt::format("/state/neighbour_offsets[0] = {}, not 0", offsets[0]));
  for (std::size_t i = 0; i < n; ++i)
    if (offsets[i + 1] < offsets[i])
      fail(fmt::format("{} = {} is below the entry before it ({}): offsets must not decrease",
                       at("/state/neighbour_offsets", i + 1), offsets[i + 1], offsets[i]));
  if (std::size_t(offsets[n]) != s.neighbours.size())
    fail(fmt::format("/state/neighbour_offsets[{}] = {}, but /state/neighbours has {} entries", n,
                     offsets[n], s.neighbours.size()));
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = offsets[i]; k < offsets[i + 1]; ++k) {
      const int j = s.neighbours[std::size_t(k)];
      if (j < 0 || std::size_t(j) >= n)
        fail(fmt::format("{} = {} is not a particle index in [0, {})",
                         at("/state/neighbours", std::size_t(k)), j, n));
      if (std::size_t(j) == i)
        fail(fmt::format("{} = {}: particle {} lists itself",
                         at("/state/neighbours", std::size_t(k)), j, i));
    }
  }
}

void check_ids(const SolverState& s) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.id[i] < 0 || s.id[i] >= s.next_id)
      fail(fmt::format("{} = {} is not in [0, /state@next_id = {})", at("/state/id", i), s.id[i],
                       s.next_id));
  std::vector<int> sorted = s.id;
  std::sort(sorted.begin(), sorted.end());
  const auto twin = std::adjacent_find(sorted.begin(), sorted.end());
  if (twin != sorted.end()) fail(fmt::format("/state/id holds id {} twice", *twin));
}

// Partners are ids (-1: free slot), distinct within a particle and not its own; a free
// slot's spring is zero (the force kernel clears it when it frees or claims the slot).
void check_history(const SolverState& s) {
  const std::size_t slots = std::size_t(s.history_slots), dim = std::size_t(s.dim);
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t a = 0; a < slots; ++a) {
      const std::size_t k = i * slots + a;
      const int partner = s.history_partner[k];
      if (partner == -1) {
        for (std::size_t d = 0; d < dim; ++d)
          if (s.history_spring[k * dim + d] != 0)
            fail(fmt::format("{} = {} belongs to a free slot (/state/history_partner[{}] = -1)",
                             at("/state/history_spring", k * dim + d),
                             s.history_spring[k * dim + d], k));
        continue;
      }
      if (partner < 0 || partner >= s.next_id)
        fail(fmt::format("{} = {} is neither -1 nor an id in [0, /state@next_id = {})",
                         at("/state/history_partner", k), partner, s.next_id));
      if (partner == s.id[i])
        fail(fmt::format("{} = {} is the particle's own id", at("/state/history_partner", k),
                         partner));
      for (std::size_t b = 0; b < a; ++b)
        if (s.history_partner[i * slots + b] == partner)
          fail(fmt::format("{} = {} repeats slot {} of the same particle",
                           at("/state/history_partner", k), partner, b));
    }
  }
}

}  // namespace

void check_state(const SolverState& s) {
  check_counters(s);
  check_shapes(s);
  for (const auto& [name, values] :
       {std::pair<const char*, const std::vector<double>*>{"/state/position", &s.position},
        {"/state/velocity", &s.velocity},
        {"/state/force", &s.force},
        {"/state/angular_velocity", &s.angular_velocity},
        {"/state/torque", &s.torque},
        {"/state/history_spring", &s.history_spring},
        {"/state/history_obstacle_spring", &s.history_obstacle_spring},
        {"/state/contact_virial", &s.contact_virial},
        {"/state/reference_position", &s.reference_position}})
    expect_finite(name, *values);
  check_neighbours(s);
  check_ids(s);
  check_history(s);
}

void check_extras(const CheckpointExtras& e) {
  if (e.inserted < 0) fail(fmt::format("/run@inserted = {} is negative", e.inserted));
  if (e.deleted_outlet < 0)
    fail(fmt::format("/run@deleted_outlet = {} is negative", e.deleted_outlet));
  if (e.deleted_inlet < 0)
    fail(fmt::format("/run@deleted_inlet = {} is negative", e.deleted_inlet));
  if (!std::isfinite(e.insertion_carry) || e.insertion_carry < 0)
    fail(fmt::format("/run@insertion_carry = {} is not a finite count >= 0", e.insertion_carry));
  if (!std::isfinite(e.wall_seconds_so_far) || e.wall_seconds_so_far < 0)
    fail(fmt::format("/run@wall_seconds_so_far = {} is not a finite time >= 0",
                     e.wall_seconds_so_far));
  if (!std::isfinite(e.cpu_seconds_so_far) ||
      (e.cpu_seconds_so_far < 0 && e.cpu_seconds_so_far != -1))
    fail(
        fmt::format("/run@cpu_seconds_so_far = {} is neither a finite time >= 0 nor -1 "
                    "(not recorded)",
                    e.cpu_seconds_so_far));
  if (!e.run_id.empty() && (e.run_frames < 0 || e.run_rows < 0))
    fail(fmt::format("/run@run_file_frames = {} and @run_file_rows = {} are not counts >= 0",
                     e.run_frames, e.run_rows));

  const std::vector<long>& shape = e.bin_shape;
  if (shape.empty() && e.bin_sums.empty()) return;  // a run without field sums
  if (shape.size() != 3)
    fail(fmt::format("/run/bin_shape has {} entries, expected 3 (grid, profile, blocks)",
                     shape.size()));
  long total = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    if (shape[k] < 0 || std::size_t(shape[k]) > e.bin_sums.size())
      fail(fmt::format("{} = {} is not a length in [0, {}] (/run/bin_sums)",
                       at("/run/bin_shape", k), shape[k], e.bin_sums.size()));
    total += shape[k];
  }
  if (std::size_t(total) != e.bin_sums.size())
    fail(fmt::format("/run/bin_shape = [{}, {}, {}] adds up to {}, but /run/bin_sums has {} values",
                     shape[0], shape[1], shape[2], total, e.bin_sums.size()));
  expect_finite("/run/bin_sums", e.bin_sums);
  for (std::size_t k = std::size_t(shape[0] + shape[1]); k < e.bin_sums.size(); ++k) {
    const double samples = e.bin_sums[k];
    if (samples < 0 || samples != std::floor(samples))
      fail(fmt::format("{} = {} is a sample count, not a whole number >= 0", at("/run/bin_sums", k),
                       samples));
  }
}

}  // namespace granshock

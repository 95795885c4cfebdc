#include "core/particle_bytes.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace granshock {

namespace {

// Every per-particle vector of one or more states, in one fixed order: f(a.position,
// b.position, ...), and so on. The neighbour list is not per particle (it indexes the
// whole state).
template <class F, class... States>
void for_each_vector(F&& f, States&... s) {
  f(s.position...);
  f(s.velocity...);
  f(s.force...);
  f(s.angular_velocity...);
  f(s.torque...);
  f(s.species...);
  f(s.id...);
  f(s.history_partner...);
  f(s.history_spring...);
  f(s.history_obstacle_spring...);
  f(s.contact_virial...);
  f(s.reference_position...);
}
template <class F, class... Particles>
void for_each_host_vector(F&& f, Particles&... p) {
  f(p.position...);
  f(p.velocity...);
  f(p.angular_velocity...);
  f(p.species...);
  f(p.id...);
}

template <class T>
void put(std::vector<char>& out, const std::vector<T>& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::uint64_t n = v.size();
  const char* head = reinterpret_cast<const char*>(&n);
  out.insert(out.end(), head, head + sizeof n);
  const char* data = reinterpret_cast<const char*>(v.data());
  out.insert(out.end(), data, data + n * sizeof(T));
}

// Appends the vector at `at` to v and moves `at` past it.
template <class T>
void take(const std::vector<char>& in, std::size_t& at, std::vector<T>& v) {
  std::uint64_t n = 0;
  if (at + sizeof n > in.size()) throw std::logic_error("particle bytes cut short");
  std::memcpy(&n, in.data() + at, sizeof n);
  at += sizeof n;
  if (at + n * sizeof(T) > in.size()) throw std::logic_error("particle bytes cut short");
  const std::size_t old = v.size();
  v.resize(old + n);
  std::memcpy(static_cast<void*>(v.data() + old), in.data() + at, n * sizeof(T));
  at += n * sizeof(T);
}

// Replaces `to` by the rows of `from` (a vector of n particles' values, width each).
template <class T>
void select_rows(const std::vector<T>& from, std::size_t n, const std::vector<int>& rows,
                 std::vector<T>& to) {
  const std::size_t width = n == 0 ? 0 : from.size() / n;
  to.clear();
  for (const int r : rows)
    to.insert(to.end(), from.begin() + long(r * width), from.begin() + long((r + 1) * width));
}

}  // namespace

std::vector<char> pack_particles(const SolverState& s) {
  std::vector<char> out;
  for_each_vector([&](const auto& v) { put(out, v); }, s);
  return out;
}
std::vector<char> pack_particles(const HostParticles& p) {
  std::vector<char> out;
  for_each_host_vector([&](const auto& v) { put(out, v); }, p);
  return out;
}

void append_particles(const std::vector<char>& parts, SolverState& into) {
  for (std::size_t at = 0; at < parts.size();)
    for_each_vector([&](auto& v) { take(parts, at, v); }, into);
}
void append_particles(const std::vector<char>& parts, HostParticles& into) {
  for (std::size_t at = 0; at < parts.size();)
    for_each_host_vector([&](auto& v) { take(parts, at, v); }, into);
}

SolverState select_particles(const SolverState& s, const std::vector<int>& rows) {
  SolverState out = s;
  for_each_vector([&](const auto& from, auto& to) { select_rows(from, s.size(), rows, to); }, s,
                  out);
  out.neighbour_offsets.clear();
  out.neighbours.clear();
  return out;
}

HostParticles select_particles(const HostParticles& p, const std::vector<int>& rows) {
  HostParticles out;
  for_each_host_vector([&](const auto& from, auto& to) { select_rows(from, p.size(), rows, to); },
                       p, out);
  return out;
}

}  // namespace granshock

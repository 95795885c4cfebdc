// The fused step: one pass per time step instead of three (docs/design.md, "The solver").
// Velocity Verlet split into half steps (velocity_verlet.hpp) runs, between two list
// checks, forces -> second half of step n -> first half of step n+1; the fused kernel does
// the three for each particle in one pass, with the force kept in registers (on a host, in
// a local array for the run of particles a work item moves):
//   f_i  = F(x^{n+1}, v^{n+1/2})                       (contact_forces.hpp, total())
//   v_i' = v_i + dt/2 (f_i/m_i + g);  v_i'' = v_i' + dt/2 (f_i/m_i + g);  x_i' = x_i + dt v_i''
// Each partner's position and velocity are read while other threads move theirs, so the
// new positions, velocities (and spins) go to second buffers that the solver swaps in
// afterwards. The arithmetic, operation for operation, is that of the separate halves, so
// the trajectory is bitwise the same (tests/reference/check_bitwise.sh).
// Positions are Position (double) in every variant (device/position.hpp). The forces are
// not stored. The closing pass (Closing) ends a call of advance(): the forces, each
// particle's contact virial (for a field sample) and the second half of the step only,
// and it stores f (the next call's first half reads it), so that a caller always finds f,
// v and x of the same step. It runs over the same runs of particles, with the same marks,
// as the fused step, instead of a force pass over all particles and a kick after it.
// What the pass reduces is chosen per step (neighbours/rebuild_watch.hpp): the largest
// squared displacement since the last list build, or, while a bound on it suffices, the
// largest squared speed, which spares the load of every particle's reference position.
#pragma once

#include <Kokkos_Core.hpp>
#include <cstdint>

#include "kernels/device/backends.hpp"
#include "kernels/device/row_element.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/particles/variant_types.hpp"
#include "kernels/solver/contact_forces.hpp"
#include "kernels/solver/kick.hpp"
#include "kernels/solver/run_marks.hpp"

namespace granshock {

template <class V, class ExecSpace, class Paths = DefaultPaths<ExecSpace>, bool Closing = false>
struct FusedStepKernel {
  using Types = VariantTypes<V, ExecSpace>;
  static constexpr int Dim = Types::Dim;
  using Real = typename Types::Real;
  using Mem = typename Types::Mem;
  using Store = typename Types::Store;
  using Position = typename Types::Position;
  using VectorView = typename Store::VectorView;
  using SpinView = typename Store::SpinView;
  using SpinValue = Spin<Dim, Real>;  // device/spin.hpp

  using Forces =
      ContactForceKernel<V, ExecSpace, Closing ? ForceMode::forces_and_virial : ForceMode::forces>;
  Forces forces;                        // reads the current x, v (and spin)
  typename Store::PositionView x_next;  // not in the closing pass, which moves nothing
  VectorView v_next;
  SpinView omega_next;  // with friction
  Vec<Dim, Real> gravity;
  bool report_speed;  // reduce max |v|^2 instead of the displacement since the last build

  int n;  // particles
  // Which work items may touch the obstacle, and which hold a particle that may have a
  // partner across a periodic face (run_marks.hpp), known for the first `runs_known`; the
  // others' particles are treated as marked. Host paths: the span of a run's particles
  // that form the image.
  Kokkos::View<const std::uint8_t*, Mem> run_marks;
  int runs_known = 0;
  Kokkos::View<const int* [2], Mem> image_spans;

  // Host paths give each work item a run of particles, so that the running maximum and
  // the step's constants stay in registers: through the reference `worst` and the
  // functor's own fields, which the compiler must assume the stores to x_next and v_next
  // may overwrite, they are reloaded per particle. Device paths keep one particle per
  // thread (neighbouring threads, neighbouring particles: coalesced loads).
  static constexpr int run_length = Paths::host ? 64 : 1;
  KOKKOS_INLINE_FUNCTION static int work_items(int particles) {
    return (particles + run_length - 1) / run_length;
  }

  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int run, Real& worst) const {
    advance_run(run, report_speed, worst);
  }
  // The closing pass reports nothing.
  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int run) const {
    Real unused = 0;
    advance_run(run, false, unused);
  }

  // One work item's particles; by_speed as report_speed, given apart for the chained
  // steps of device paths, whose device-side watch decides it (chained_steps.hpp).
  KOKKOS_FORCEINLINE_FUNCTION void advance_run(const int run, const bool by_speed,
                                               Real& worst) const {
    const int first = run * run_length;
    const int last = first + run_length < n ? first + run_length : n;
    // On a host, two loops over the run: the forces of all its particles, kept in a local
    // array, then their kicks and drifts. Each loop keeps its own values in registers; in
    // one loop the pair loop's box, reach and partner views and the kick's velocities and
    // constants together did not fit, and the compiler kept them on the stack, for every
    // particle (docs/benchmarks.md, "Instructions per particle-step"). The kick's
    // constants are read after the first loop for the same reason. The arithmetic is the
    // same, so the trajectory is bitwise the same.
    Vec<Dim, Real> f[run_length];
    SpinValue torque[run_length];
    const std::uint8_t marks = run < runs_known ? run_marks(run) : run_mark::all;
    if (marks & run_mark::obstacle) {
      forces_of_run<V::obstacle::present>(run, first, last, marks, f, torque);
    } else {
      forces_of_run<false>(run, first, last, marks, f, torque);
    }
    const Real half = Real(0.5) * forces.dt, step = forces.dt;
    const Vec<Dim, Real> g = gravity;
    if constexpr (Closing) {
      (void)by_speed, (void)step, (void)worst;
      for (int i = first; i < last; ++i) close(i, f[i - first], torque[i - first], half, g);
    } else {
      Real largest = worst;
      if (by_speed) {  // the test out of the loop
        for (int i = first; i < last; ++i)
          move<true>(i, f[i - first], torque[i - first], half, step, g, largest);
      } else {
        for (int i = first; i < last; ++i)
          move<false>(i, f[i - first], torque[i - first], half, step, g, largest);
      }
      if (largest > worst) worst = largest;
    }
  }

  // The forces and torques on particles [first, last) of work item `run` (with its marks)
  // into f and torque. WithObstacle false: they are known not to touch the obstacle
  // (run_marks.hpp). On host paths only the run's span of particles near a periodic face
  // forms the image, in a function of its own: inlined, its code and the loops' took
  // registers from the hot loops, which then kept their counters on the stack
  // (docs/benchmarks.md, "Instructions per particle-step"). The order in which particles
  // are taken does not matter: each writes only its own force, torque and springs.
  template <bool WithObstacle>
  KOKKOS_FORCEINLINE_FUNCTION void forces_of_run(const int run, const int first, const int last,
                                                 const std::uint8_t marks, Vec<Dim, Real>* f,
                                                 SpinValue* torque) const {
    if constexpr (Paths::host) {
      int begin = last, end = last;  // the span that forms the image
      if (run >= runs_known)
        begin = first;
      else if (marks & run_mark::image)
        begin = image_spans(run, 0), end = image_spans(run, 1);
      for (int i = first; i < begin; ++i)
        force<WithObstacle, false>(i, f[i - first], torque[i - first]);
      if (begin < end) forces_with_image<WithObstacle>(first, begin, end, f, torque);
      for (int i = end; i < last; ++i)
        force<WithObstacle, false>(i, f[i - first], torque[i - first]);
    } else {  // a GPU thread's particle always forms the image
      forces_with_image<WithObstacle>(first, first, last, f, torque);
    }
  }

  // Particles [begin, end) of the run from `first`, with the image.
  template <bool WithObstacle>
  GRANSHOCK_HOST_NOINLINE KOKKOS_INLINE_FUNCTION void forces_with_image(
      const int first, const int begin, const int end, Vec<Dim, Real>* f, SpinValue* torque) const {
    for (int i = begin; i < end; ++i) force<WithObstacle, true>(i, f[i - first], torque[i - first]);
  }

  // Without friction the torque goes to a local the compiler drops: written to the run's
  // array it was a store per particle that nothing reads. The closing pass writes each
  // particle's contact virial as the force pass of ForceMode::forces_and_virial does.
  template <bool WithObstacle, bool Images>
  KOKKOS_FORCEINLINE_FUNCTION void force(const int i, Vec<Dim, Real>& f, SpinValue& torque) const {
    const Vec<Dim, Position> xi = forces.pairs.position(i);
    using ReadOwnVelocity = typename Forces::ReadOwnVelocity;
    SpinValue dropped;
    SpinValue& kept = kept_torque(torque, dropped);
    if constexpr (Closing) {
      Real w[Dim * Dim] = {};
      forces.template total<WithObstacle, Images>(i, xi, ReadOwnVelocity{}, f, kept, w);
      for (int k = 0; k < Dim * Dim; ++k) forces.virial(i, k) = w[k];
    } else {
      forces.template total<WithObstacle, Images>(i, xi, ReadOwnVelocity{}, f, kept);
    }
  }
  KOKKOS_FORCEINLINE_FUNCTION static SpinValue& kept_torque(SpinValue& torque, SpinValue& dropped) {
    if constexpr (V::friction) {
      (void)dropped;
      return torque;
    } else {
      (void)torque;
      return dropped;
    }
  }

  // The kicks and the drift of particle i under force f (and torque), written to the
  // second buffers; worst gets the particle's squared speed (BySpeed) or displacement.
  template <bool BySpeed>
  KOKKOS_FORCEINLINE_FUNCTION void move(const int i, const Vec<Dim, Real>& f,
                                        const SpinValue& torque, const Real half, const Real step,
                                        const Vec<Dim, Real>& g, Real& worst) const {
    const auto& p = forces.p;
    const Vec<Dim, Position> xi = forces.pairs.position(i);
    const Vec<Dim, Real> vi = forces.velocity(i);
    const int s = p.species(i);
    const Real im = forces.table.inv_mass(s);
    // d2 starts from the first square, not from 0: 0 + a square is that square (both are
    // >= +0), and the compiler may not drop the addition itself.
    Real d2 = 0;
    for (int d = 0; d < Dim; ++d) {
      Real v = vi[d];
      half_kick(v, half, f[d], im, g[d]);   // second half of this step
      half_kick(v, half, f[d], im, g[d]);   // first half of the next
      const Position x = xi[d] + step * v;  // the drift: a Real step onto a Position
      row_element(v_next, i, d) = v;
      row_element(x_next, i, d) = x;
      Real square;
      if constexpr (BySpeed) {
        square = v * v;
      } else {
        const Real moved = Real(x - row_element(p.x_ref, i, d));
        square = moved * moved;
      }
      d2 = d == 0 ? square : d2 + square;
    }
    if constexpr (V::friction) {
      const Real ii = forces.table.inv_inertia(s);
      SpinValue w = load_spin<Dim>(p.omega, i);
      half_spin_kick(w, half, torque, ii);
      half_spin_kick(w, half, torque, ii);
      store_spin<Dim>(omega_next, i, w);
    } else {
      (void)torque;
    }
    if (d2 > worst) worst = d2;
  }

  // The closing pass' end of particle i's step: f (and the torque) stored, the second half
  // kick of the velocity (and spin) written to the second buffers; x stays.
  KOKKOS_FORCEINLINE_FUNCTION void close(const int i, const Vec<Dim, Real>& f,
                                         const SpinValue& torque, const Real half,
                                         const Vec<Dim, Real>& g) const {
    const auto& p = forces.p;
    const Vec<Dim, Real> vi = forces.velocity(i);
    const int s = p.species(i);
    const Real im = forces.table.inv_mass(s);
    for (int d = 0; d < Dim; ++d) {
      Real v = vi[d];
      half_kick(v, half, f[d], im, g[d]);
      row_element(v_next, i, d) = v;
      p.f(i, d) = f[d];
    }
    if constexpr (V::friction) {
      store_spin<Dim>(p.torque, i, torque);
      SpinValue w = load_spin<Dim>(p.omega, i);
      half_spin_kick(w, half, torque, forces.table.inv_inertia(s));
      store_spin<Dim>(omega_next, i, w);
    } else {
      (void)torque;
    }
  }
};

}  // namespace granshock

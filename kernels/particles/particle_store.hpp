// Particle storage on the device: a structure of arrays of Kokkos Views, each declared
// once (docs/design.md, "Particles"). for_each_array() lists every per-particle array with
// its name, the SolverState member that checkpoints it, what a ghost carries of it and its
// value before anything is known; allocation, growth, permutation after a cell sort, the
// state's export and import, particles given by position and velocity, and the slab
// exchange's ghosts all iterate that list, so a new per-particle quantity is one line
// there and one member of SolverState.
// Owned particles occupy [0, n); the Views have spare capacity so that particles can be
// inserted and removed (and, with domain decomposition, ghosts appended after the owned
// ones) without a reallocation each step. Positions (x, x_ref) are always stored as
// Position, double, in every precision variant (device/position.hpp; docs/design.md,
// "Particles"); the other vectors as Real. Vectors are View<T*[Dim]>: contiguous
// components per particle on the host (LayoutRight), one array per component on a GPU
// (LayoutLeft), each the coalesced layout for its backend. A frictionless scene allocates
// no rotation and no contact history (docs/design.md, "The variant table").
#pragma once

#include <Kokkos_Core.hpp>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/solver_state.hpp"
#include "kernels/device/device_lambda.hpp"
#include "kernels/device/position.hpp"
#include "kernels/device/spin.hpp"
#include "kernels/particles/reorder.hpp"

namespace granshock {

// What a per-particle array is to the processes around it (particles/slab_exchange.hpp):
// a ghost carries the arrays a partner's force reads; between rebuilds a ghost's update
// carries the ones that move.
enum ArrayRole : unsigned { kept_at_home = 0, read_by_partners = 1, moves = 2 };

// A per-particle array's name, where a checkpoint keeps it, its roles (ArrayRole bits) and
// the value a particle holds before anything is known of it (a fresh store, particles
// given by position and velocity: StateTransfer::set_particles).
// (The member pointer has a type alias: nvcc rewrote the plain declarator with
// parentheses, and g++ warned about them in the CUDA build.)
template <class Host>
struct StateArray {
  using Member = std::vector<Host> SolverState::*;
  const char* name;
  Member member;
  unsigned roles = kept_at_home;
  Host rest = 0;
  // A state may lack it (a format-3 checkpoint written before it was kept,
  // io/checkpoint_file.hpp): the array then holds `rest`
  // and the solver knows it was not given (StateTransfer::import_state).
  bool may_be_absent = false;
};

template <int Dim, class Real, class MemSpace, bool Friction>
struct ParticleStore {
  static constexpr int dim = Dim;
  static constexpr bool friction = Friction;
  // Tangential springs per particle: more than the contacts a sphere can have.
  static constexpr int history_slots = Dim == 2 ? 8 : 16;

  using Position = granshock::Position;  // double: device/position.hpp
  using PositionView = Kokkos::View<Position* [Dim], MemSpace>;
  using VectorView = Kokkos::View<Real* [Dim], MemSpace>;
  using ScalarView = Kokkos::View<Real*, MemSpace>;
  using IntView = Kokkos::View<int*, MemSpace>;
  using PartnerView = Kokkos::View<int* [history_slots], MemSpace>;
  using SpringView = Kokkos::View<Real * [history_slots * Dim], MemSpace>;
  using VirialView = Kokkos::View<Real * [Dim * Dim], MemSpace>;
  // Angular velocity and torque: about z in 2-D, vectors in 3-D (device/spin.hpp).
  using SpinView = std::conditional_t<Dim == 2, ScalarView, VectorView>;

  PositionView x;      // positions
  PositionView x_ref;  // positions at the last neighbour-list build (the skin criterion)
  VectorView v, f;
  IntView species;
  IntView id;  // global id, never reused within a run
  // With friction: spin (about z in 2-D) and its torque, and the tangential springs, kept
  // per partner's global id so that they survive rebuilds and reordering without
  // remapping. Only the thread handling particle i touches i's slots (full neighbour list).
  SpinView omega, torque;
  PartnerView history_partner;  // partner global id per slot, -1 when free
  SpringView history_spring;    // spring xi per slot
  VectorView obstacle_spring;   // spring xi against the obstacle
  // The contact virial W_i = sum_j 1/2 r_ij (x) F_ij of the last force pass that recorded
  // it (the step's last: StepLoop::close_step, or compute_forces), for field sampling
  // (docs/fields.md, "The contact virial"); 0 for a particle inserted since, which touched
  // nothing.
  VirialView virial;
  int n = 0;  // owned particles

  // Calls visit(StateArray, view...) for every per-particle array of this variant, with
  // that array of each of the given stores (one store: its arrays; two: pairs).
  template <class Visit, class... Stores>
  static void for_each_array(Visit&& visit, Stores&... stores) {
    constexpr unsigned motion = read_by_partners | moves;
    visit(StateArray<double>{"position", &SolverState::position, motion}, stores.x...);
    visit(StateArray<double>{"velocity", &SolverState::velocity, motion}, stores.v...);
    visit(StateArray<double>{"force", &SolverState::force}, stores.f...);
    visit(StateArray<double>{"reference_position", &SolverState::reference_position},
          stores.x_ref...);
    visit(StateArray<int>{"species", &SolverState::species, read_by_partners}, stores.species...);
    visit(StateArray<int>{"id", &SolverState::id, read_by_partners}, stores.id...);
    if constexpr (Friction) {
      visit(StateArray<double>{"angular_velocity", &SolverState::angular_velocity, motion},
            stores.omega...);
      visit(StateArray<double>{"torque", &SolverState::torque}, stores.torque...);
      // -1: a free slot (no partner).
      visit(StateArray<int>{"history_partner", &SolverState::history_partner, kept_at_home, -1},
            stores.history_partner...);
      visit(StateArray<double>{"history_spring", &SolverState::history_spring},
            stores.history_spring...);
      visit(StateArray<double>{"history_obstacle_spring", &SolverState::history_obstacle_spring},
            stores.obstacle_spring...);
    }
    visit(StateArray<double>{"contact_virial", &SolverState::contact_virial, kept_at_home, 0, true},
          stores.virial...);
  }

  int capacity() const { return int(x.extent(0)); }

  void allocate(int capacity) {
    for_each_array(
        [&](auto array, auto& view) {
          view = std::decay_t<decltype(view)>(std::string(array.name), capacity);
          if (array.rest != 0) Kokkos::deep_copy(view, array.rest);  // Views start at zero
        },
        *this);
  }
};

// Copies the first n particles of every array of `from` into `to` (of larger capacity).
template <class ExecSpace, class Store>
void copy_particles(Store& to, const Store& from, int n) {
  Store::for_each_array(
      [&](auto, auto& dst, const auto& src) { copy_prefix<ExecSpace>(dst, src, n); }, to, from);
  to.n = n;
}

// Reorders every array: new index k holds old particle order(k). Scratch buffers are
// one per array type and swapped with the arrays (reorder.hpp), so a permutation
// allocates nothing in steady state.
template <class ExecSpace, class Store>
class ParticlePermutation {
 public:
  template <class OrderView>
  void apply(Store& p, const OrderView& order, int n) {
    Store::for_each_array(
        [&](auto, auto& view) {
          using View = std::decay_t<decltype(view)>;
          gather_in_place<ExecSpace>(view, std::get<View>(scratch_), order, n);
        },
        p);
  }

 private:
  // One scratch buffer per distinct array type (std::get by type needs each once): in the
  // double variant positions and the other vectors share a type.
  using Common = std::tuple<typename Store::VectorView, typename Store::ScalarView,
                            typename Store::IntView, typename Store::PartnerView,
                            typename Store::SpringView, typename Store::VirialView>;
  using Scratch = std::conditional_t<
      std::is_same_v<typename Store::PositionView, typename Store::VectorView>, Common,
      decltype(std::tuple_cat(std::declval<std::tuple<typename Store::PositionView>>(),
                              std::declval<Common>()))>;
  Scratch scratch_;
};

}  // namespace granshock

// Every choice a user makes by name, one table each (docs/design.md, "Names of choices"):
// the only place in the code where these names are written. Parsing, the resolved scene,
// the scene schema's lists, the command line's checks and help and `granshock info` derive
// from the tables (core/choice.hpp); tests/scene/test_choice_names.cpp and
// tests/cli/every_choice_name.sh check each name through each of them. The names of what
// the variant table compiles (contact laws, obstacle shapes, precisions) are in
// core/variant_names.hpp.
#pragma once

#include "core/bin_layout.hpp"
#include "core/choice.hpp"
#include "core/contact_settings.hpp"
#include "core/kinetic_theory.hpp"
#include "core/run_modes.hpp"
#include "core/scene.hpp"
#include "core/solver.hpp"
#include "core/solver_setup.hpp"
#include "core/variant_names.hpp"

namespace granshock {

template <>
struct Choices<RestitutionMode> {
  static constexpr const char* what = "restitution mode";
  static constexpr ChoiceName<RestitutionMode> table[] = {
      {RestitutionMode::continuous, "continuous",
       "damping from e by the law's closed form, exact as dt -> 0"},
      {RestitutionMode::discrete, "discrete",
       "damping calibrated so that the integrator at the run's dt returns e"},
  };
};

template <>
struct Choices<ScatterStrategy> {
  static constexpr const char* what = "field scatter";
  static constexpr ChoiceName<ScatterStrategy> table[] = {
      {ScatterStrategy::automatic, "auto",
       "rows on a host backend with at most 16 threads, atomic otherwise"},
      {ScatterStrategy::atomic, "atomic", "atomic adds"},
      {ScatterStrategy::scatter_view, "scatter_view", "a Kokkos ScatterView"},
      {ScatterStrategy::rows, "rows",
       "rows of bins owned by threads, bitwise the same for any thread count"},
  };
};

template <>
struct Choices<MassDefinition> {
  static constexpr const char* what = "mass definition";
  static constexpr ChoiceName<MassDefinition> table[] = {
      {MassDefinition::mixture_mean, "mixture_mean", "the mixture's mean mass sum_a xi_a m_a"},
      {MassDefinition::paper_sum, "paper_sum", "the paper's sum of the species' masses"},
  };
};

template <>
struct Choices<MachReference> {
  static constexpr const char* what = "mach reference";
  static constexpr ChoiceName<MachReference> table[] = {
      {MachReference::inserted, "inserted", "the Mach number of the inserted state"},
      {MachReference::inlet_bins, "inlet_bins",
       "measured over the two inlet bin rows; sigma calibrated before the run"},
  };
};

template <>
struct Choices<ZBoundary> {
  static constexpr const char* what = "z boundary";
  static constexpr ChoiceName<ZBoundary> table[] = {
      {ZBoundary::walls, "walls", "flat frictionless walls at z = 0 and z = thickness"},
      {ZBoundary::periodic, "periodic", "a periodic z axis"},
  };
};

template <>
struct Choices<SlabAxis> {
  static constexpr const char* what = "slab axis";
  static constexpr ChoiceName<SlabAxis> table[] = {
      {SlabAxis::x, "x", "slabs across the flow, through the periodic faces"},
      {SlabAxis::y, "y", "slabs along the flow"},
  };
};

template <>
struct Choices<SlabBalance> {
  static constexpr const char* what = "balance";
  static constexpr ChoiceName<SlabBalance> table[] = {
      {SlabBalance::equal, "equal", "slabs of equally many cell rows"},
      {SlabBalance::particles, "particles",
       "boundaries moved at list rebuilds to balance the particles"},
      {SlabBalance::work, "work", "boundaries moved at list rebuilds to balance the measured work"},
  };
};

template <>
struct Choices<SnapshotOutput> {
  static constexpr const char* what = "snapshot output";
  static constexpr ChoiceName<SnapshotOutput> table[] = {
      {SnapshotOutput::automatic, "auto",
       "collective for frames of 24,576 particles or more, gathered otherwise"},
      {SnapshotOutput::gathered, "gathered", "gathered to rank 0, written there"},
      {SnapshotOutput::collective, "collective",
       "written by every process at once (parallel HDF5)"},
  };
};

template <>
struct Choices<BackendSwitchMode> {
  static constexpr const char* what = "backend switch";
  static constexpr ChoiceName<BackendSwitchMode> table[] = {
      {BackendSwitchMode::automatic, "auto",
       "one thread while the threads run slower than one would, the threads again later"},
      {BackendSwitchMode::off, "off", "keep the threads"},
      {BackendSwitchMode::alternate, "alternate",
       "move at every slice (a check that both give the same run)"},
  };
};

template <>
struct Choices<ThreadShareMode> {
  static constexpr const char* what = "thread shares";
  static constexpr ChoiceName<ThreadShareMode> table[] = {
      {ThreadShareMode::by_time, "by_time",
       "each thread's particles cut by the time the threads took before"},
      {ThreadShareMode::equal, "equal", "equally many particles per thread"},
      {ThreadShareMode::alternating, "alternating",
       "cuts moved at every region of steps (a check that they change nothing)"},
  };
};

template <>
struct Choices<ImpactLine> {
  static constexpr const char* what = "line of impact";
  static constexpr ChoiceName<ImpactLine> table[] = {
      {ImpactLine::x, "x", "the bodies approach along x"},
      {ImpactLine::y, "y", "the bodies approach along y"},
  };
};

template <>
struct Choices<BatchScript> {
  static constexpr const char* what = "batch script";
  static constexpr ChoiceName<BatchScript> table[] = {
      {BatchScript::slurm, "slurm", "a Slurm array job, one task per case"},
  };
};

static_assert(choice_table_is_one_to_one<RestitutionMode>());
static_assert(choice_table_is_one_to_one<ScatterStrategy>());
static_assert(choice_table_is_one_to_one<MassDefinition>());
static_assert(choice_table_is_one_to_one<MachReference>());
static_assert(choice_table_is_one_to_one<ZBoundary>());
static_assert(choice_table_is_one_to_one<SlabAxis>());
static_assert(choice_table_is_one_to_one<SlabBalance>());
static_assert(choice_table_is_one_to_one<SnapshotOutput>());
static_assert(choice_table_is_one_to_one<BackendSwitchMode>());
static_assert(choice_table_is_one_to_one<ThreadShareMode>());
static_assert(choice_table_is_one_to_one<ImpactLine>());
static_assert(choice_table_is_one_to_one<BatchScript>());

// Calls f(Enum{}) for every choice's enum, for the tests and `granshock info`.
template <class F>
void for_each_choice(F&& f) {
  f(ContactModelKind{}), f(RestitutionMode{}), f(Precision{}), f(ScatterStrategy{});
  f(MassDefinition{}), f(MachReference{}), f(SlabAxis{}), f(SlabBalance{});
  f(SnapshotOutput{}), f(BackendSwitchMode{}), f(ThreadShareMode{}), f(ObstacleShape{});
  f(ImpactLine{}), f(BatchScript{}), f(ZBoundary{});
}

}  // namespace granshock

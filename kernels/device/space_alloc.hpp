// Views allocated by the kernels' own execution space. Kokkos initialises a new View, and
// fills a host View, on the default execution space of the View's memory space: for
// HostSpace that is OpenMP even when the kernels run on Serial. A solver moved to one
// thread beside a busy process (docs/benchmarks.md, "A busy machine") then still waited at
// an OpenMP region, for a thread the kernel had descheduled, at every list build. Views
// that the solver makes while it runs are therefore made, filled and copied on ExecSpace.
#pragma once

#include <Kokkos_Core.hpp>
#include <string>

namespace granshock {

// The allocation properties of a View that ExecSpace zero-initialises.
template <class ExecSpace>
auto alloc_on(const std::string& label) {
  return Kokkos::view_alloc(ExecSpace(), label);
}

// The same without initialisation, for scratch arrays that are written before they are read.
template <class ExecSpace>
auto alloc_uninitialised_on(const std::string& label) {
  return Kokkos::view_alloc(ExecSpace(), label, Kokkos::WithoutInitializing);
}

}  // namespace granshock

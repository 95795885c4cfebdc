// Host copies of device Views, made as a GPU needs them (docs/cuda.md, "Branch points").
// Where the host can read a View, Kokkos' mirror is the View itself, and a deep_copy
// between the two does nothing; on a GPU the mirror is a separate array. On device paths
// (device/backends.hpp) the mirror is a separate host array on a host backend too, so that
// a host write never copied back to the device, or a read of the mirror before the copy,
// goes wrong on the host as it would on a GPU. Paths is the caller's KernelPaths, always
// given: a part of a solver built for the other paths must not take the build's.
#pragma once

#include <Kokkos_Core.hpp>

#include "kernels/device/backends.hpp"

namespace granshock {

// A host View shaped like v, its contents undefined until copied (create_mirror_view).
template <class Paths, class View>
auto host_mirror(const View& v) {
  if constexpr (Paths::host) {
    return Kokkos::create_mirror_view(v);
  } else {
    return Kokkos::create_mirror(v);
  }
}

// A host View holding v's values (create_mirror_view_and_copy to the host).
template <class Paths, class View>
auto host_copy(const View& v) {
  if constexpr (Paths::host) {
    return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
  } else {
    auto h = Kokkos::create_mirror(Kokkos::HostSpace(), v);
    Kokkos::deep_copy(h, v);
    return h;
  }
}

// A View in memory space Mem holding the host View h's values
// (create_mirror_view_and_copy to Mem).
template <class Mem, class Paths, class HostView>
auto device_copy(const HostView& h) {
  if constexpr (Paths::host) {
    return Kokkos::create_mirror_view_and_copy(Mem(), h);
  } else {
    auto d = Kokkos::create_mirror(Mem(), h);
    Kokkos::deep_copy(d, h);
    return d;
  }
}

}  // namespace granshock

// Kokkos initialisation for granshock's programs. Kokkos 3.x prints an advisory about
// OMP_PROC_BIND on stdout when it is unset, which would corrupt JSON output. The OpenMP
// runtime has already read its environment by then, so stating its default
// (OMP_PROC_BIND=false: threads are not bound) changes nothing but the message; a
// user's own setting is kept. Thread requests past what Kokkos and the machine can take
// are lowered first (device/thread_cap.hpp).
#pragma once

#include <Kokkos_Core.hpp>
#include <cstdlib>

#include "device/thread_cap.hpp"

namespace granshock {

class KokkosRuntime {
 public:
  KokkosRuntime(int& argc, char** argv) {
    setenv("OMP_PROC_BIND", "false", /*overwrite=*/0);
    cap_host_threads(argc, argv);
    Kokkos::initialize(argc, argv);
  }
  ~KokkosRuntime() { Kokkos::finalize(); }
  KokkosRuntime(const KokkosRuntime&) = delete;
  KokkosRuntime& operator=(const KokkosRuntime&) = delete;
};

}  // namespace granshock

// Kokkos initialisation for granshock's programs. Kokkos 3.x prints an advisory about
// OMP_PROC_BIND on stdout when it is unset, which would corrupt JSON output. The OpenMP
// runtime has already read its environment by then, so stating its default
// (OMP_PROC_BIND=false: threads are not bound) changes nothing but the message; a
// user's own setting is kept. Thread requests past what Kokkos and the machine can take
// are lowered first (device/thread_cap.hpp). Kokkos also answers a plain --help (or -h)
// with its own option list and leaves it in argv: the help flags are hidden from Kokkos
// under a stand-in and given back, in place, for the program's own parser.
#pragma once

#include <Kokkos_Core.hpp>
#include <cstdlib>
#include <string_view>

#include "kernels/device/thread_cap.hpp"

namespace granshock {

class KokkosRuntime {
 public:
  KokkosRuntime(int& argc, char** argv) {
    setenv("OMP_PROC_BIND", "false", /*overwrite=*/0);
    cap_host_threads(argc, argv);
    static char help_stand_in[] = "--program-help";
    static char help[] = "--help";
    for (int k = 1; k < argc; ++k)
      if (std::string_view(argv[k]) == "--help" || std::string_view(argv[k]) == "-h")
        argv[k] = help_stand_in;
    Kokkos::initialize(argc, argv);
    for (int k = 1; k < argc; ++k)
      if (argv[k] == help_stand_in) argv[k] = help;
  }
  ~KokkosRuntime() { Kokkos::finalize(); }
  KokkosRuntime(const KokkosRuntime&) = delete;
  KokkosRuntime& operator=(const KokkosRuntime&) = delete;
};

}  // namespace granshock

#!/usr/bin/env bash
# From a fresh Debian 12 machine to a built granshock: installs the dependencies
# (cmake/install_deps.sh, idempotent), configures and builds into build/.
# Extra arguments go to the CMake configure step (e.g. -DKokkos_ROOT=/opt/kokkos).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo"
bash cmake/install_deps.sh
cmake -S . -B build -G Ninja "$@" >build-configure.log 2>&1 ||
  { cat build-configure.log >&2; exit 1; }
grep -E "granshock:" build-configure.log || true
rm -f build-configure.log
cmake --build build --parallel "$(nproc)"

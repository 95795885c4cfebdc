#!/usr/bin/env bash
# Builds Kokkos with the OpenMP and Serial backends and Kokkos' own checks on
# (Kokkos_ENABLE_DEBUG, Kokkos_ENABLE_DEBUG_BOUNDS_CHECK: every View access checks its
# indices and aborts with the View's label when one is out of range) into
# $GRANSHOCK_DEPS/kokkos-openmp-debug, idempotently (docs/cuda.md, "Bounds checking").
# The source is the one cmake/install_deps.sh unpacks from Debian's trilinos source
# package ($GRANSHOCK_DEPS/src/kokkos; install_deps.sh is run first when it is absent).
# Kokkos itself is compiled optimised (Release): the checks are macros in its headers, so
# they reach granshock's kernels whatever Kokkos' own build type. A stamp records the
# options; a second call with the same ones returns in seconds.
#
# Usage: cmake/install_kokkos_debug.sh
# Environment: GRANSHOCK_DEPS (default: <repo>/.deps) holds sources and prefixes.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps=${GRANSHOCK_DEPS:-$repo/.deps}
me=install_kokkos_debug.sh
[ $# -eq 0 ] || { echo "$me: unexpected argument '$1' (it takes none)" >&2; exit 2; }

prefix=$deps/kokkos-openmp-debug
build=$deps/build-kokkos-openmp-debug
log=$deps/build-kokkos-openmp-debug.log
options=(
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_STANDARD=17
  -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON
  -DKokkos_ENABLE_DEBUG=ON -DKokkos_ENABLE_DEBUG_BOUNDS_CHECK=ON
  -DKokkos_ENABLE_TESTS=OFF -DKokkos_ENABLE_EXAMPLES=OFF
)
stamp_text="kokkos-openmp-debug ${options[*]}"
if [ -f "$prefix/.granshock-stamp" ] && [ "$(cat "$prefix/.granshock-stamp")" = "$stamp_text" ]; then
  echo "== Kokkos (kokkos-openmp-debug): present in $prefix"
  exit 0
fi

if [ ! -f "$deps/src/kokkos/CMakeLists.txt" ]; then
  echo "== Kokkos source not in $deps/src/kokkos: running cmake/install_deps.sh"
  bash "$repo/cmake/install_deps.sh"
  [ -f "$deps/src/kokkos/CMakeLists.txt" ] ||
    { echo "$me: cmake/install_deps.sh left no Kokkos source in $deps/src/kokkos" >&2; exit 1; }
fi

echo "== building Kokkos (kokkos-openmp-debug) into $prefix (log: $log)"
start=$(date +%s)
rm -rf "$build" "$prefix"
if ! { cmake -S "$deps/src/kokkos" -B "$build" -G Ninja -DCMAKE_INSTALL_PREFIX="$prefix" \
         "${options[@]}" &&
       cmake --build "$build" --parallel "$(nproc)" &&
       cmake --install "$build"; } >"$log" 2>&1; then
  tail -n 30 "$log" >&2
  echo "$me: building Kokkos with bounds checking failed (full log: $log)" >&2
  exit 1
fi
rm -rf "$build"
echo "$stamp_text" >"$prefix/.granshock-stamp"
echo "== Kokkos (kokkos-openmp-debug) built in $(( $(date +%s) - start )) s: $prefix"

#!/usr/bin/env bash
# Builds granshock for CUDA into build-cuda/ (docs/cuda.md): every target (library,
# program, benchmarks, tests), every kernel compiled for the GPU by nvcc through
# Kokkos' nvcc_wrapper, against the Kokkos that cmake/install_kokkos_cuda.sh builds
# (run first; idempotent, seconds when it is already there). Needs nvcc, not a GPU;
# running the result (ctest --test-dir build-cuda) needs one.
#
# Usage: cmake/build_cuda.sh [extra CMake configure arguments]
# Environment: GRANSHOCK_DEPS (default: <repo>/.deps) holds the Kokkos prefix;
# GRANSHOCK_CUDA_TARGETS (default: all) names the targets to build, e.g.
# granshock_kernels, the one library that holds device code (what CI compiles).
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps=${GRANSHOCK_DEPS:-$repo/.deps}
me=build_cuda.sh
die() { echo "$me: $*" >&2; exit 1; }

if ! command -v nvcc >/dev/null 2>&1; then
  [ -x /usr/local/cuda/bin/nvcc ] ||
    die "nvcc not found (neither on PATH nor /usr/local/cuda/bin/nvcc); install the CUDA toolkit"
  export PATH=/usr/local/cuda/bin:$PATH  # nvcc_wrapper calls `nvcc` from PATH
fi

bash "$repo/cmake/install_kokkos_cuda.sh"

prefix=$deps/kokkos-cuda
build=$repo/build-cuda
log=$build/configure.log
mkdir -p "$build"
# nvcc_wrapper defaults to sm_35, which CUDA 12+ rejects; CMake's compiler checks run
# before Kokkos adds its own -arch=sm_80 (the same flag twice is accepted).
start=$(date +%s)
cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DKokkos_ROOT="$prefix" -DCMAKE_CXX_COMPILER="$prefix/bin/nvcc_wrapper" \
  -DCMAKE_CXX_FLAGS=-arch=sm_80 "$@" >"$log" 2>&1 ||
  { tail -n 30 "$log" >&2; die "configuring the CUDA build failed (full log: $log)"; }
grep -E "granshock:" "$log" || true
grep -qE "granshock: building for Kokkos backends: .*CUDA" "$log" ||
  die "the Kokkos found for build-cuda has no CUDA backend (configure log: $log)"
targets=()
for t in ${GRANSHOCK_CUDA_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build" --parallel "$(nproc)" "${targets[@]}" ||
  die "the CUDA build failed: some code does not compile for the GPU (see the errors above)"
echo "== granshock CUDA build (sm_80, ${GRANSHOCK_CUDA_TARGETS:-every target}) in $build," \
  "$(( $(date +%s) - start )) s;" \
  "tests need a GPU: ctest --test-dir $build"

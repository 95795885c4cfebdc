#!/usr/bin/env bash
# Builds Kokkos 3.4.1 with the CUDA, OpenMP and Serial backends into
# $GRANSHOCK_DEPS/kokkos-cuda, idempotently (docs/cuda.md):
#   1. copies the Kokkos source that cmake/install_deps.sh unpacks from Debian's
#      trilinos source package ($GRANSHOCK_DEPS/src/kokkos; install_deps.sh is run
#      first when it is absent) to $GRANSHOCK_DEPS/src/kokkos-cuda,
#   2. applies cmake/patches/kokkos-3.4.1-cuda13.patch (needed for CUDA 13),
#   3. configures with nvcc_wrapper for NVIDIA Ampere (sm_80; newer GPUs JIT the PTX),
#      builds and installs. The build log is $GRANSHOCK_DEPS/build-kokkos-cuda.log.
# A stamp records the patch and the options; a second call with the same ones returns
# in seconds. Needs nvcc (on PATH, or /usr/local/cuda/bin/nvcc); no GPU.
#
# Usage: cmake/install_kokkos_cuda.sh
# Environment: GRANSHOCK_DEPS (default: <repo>/.deps) holds sources and prefixes.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps=${GRANSHOCK_DEPS:-$repo/.deps}
me=install_kokkos_cuda.sh
die() { echo "$me: $*" >&2; exit 1; }
[ $# -eq 0 ] || { echo "$me: unexpected argument '$1' (it takes none)" >&2; exit 2; }

# nvcc_wrapper calls `nvcc` from PATH.
if ! command -v nvcc >/dev/null 2>&1; then
  [ -x /usr/local/cuda/bin/nvcc ] ||
    die "nvcc not found (neither on PATH nor /usr/local/cuda/bin/nvcc); install the CUDA toolkit"
  export PATH=/usr/local/cuda/bin:$PATH
fi

patch_file=$repo/cmake/patches/kokkos-3.4.1-cuda13.patch
prefix=$deps/kokkos-cuda
src=$deps/src/kokkos-cuda
build=$deps/build-kokkos-cuda
log=$deps/build-kokkos-cuda.log
options=(
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_STANDARD=17
  -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_CUDA=ON
  -DKokkos_ENABLE_CUDA_LAMBDA=ON -DKokkos_ARCH_AMPERE80=ON
  -DKokkos_ENABLE_TESTS=OFF -DKokkos_ENABLE_EXAMPLES=OFF
)
# Kokkos 3.4.1's nvcc_wrapper defaults to sm_35, which CUDA 12+ rejects: CMake's
# compiler checks fail unless the architecture is given (the same one as Kokkos_ARCH).
arch_flag=-arch=sm_80

stamp_text="kokkos-cuda $(sha256sum "$patch_file" | cut -d' ' -f1) ${options[*]} $arch_flag $(nvcc --version | tail -n 1)"
if [ -f "$prefix/.granshock-stamp" ] && [ "$(cat "$prefix/.granshock-stamp")" = "$stamp_text" ]; then
  echo "== Kokkos (kokkos-cuda): present in $prefix"
  exit 0
fi

if [ ! -f "$deps/src/kokkos/CMakeLists.txt" ]; then
  echo "== Kokkos source not in $deps/src/kokkos: running cmake/install_deps.sh"
  bash "$repo/cmake/install_deps.sh"
  [ -f "$deps/src/kokkos/CMakeLists.txt" ] || die "cmake/install_deps.sh left no Kokkos source in $deps/src/kokkos"
fi

echo "== patching a copy of the Kokkos source ($src)"
rm -rf "$src" "$build" "$prefix"
cp -a "$deps/src/kokkos/." "$src"
patch -p1 --forward --batch -d "$src" <"$patch_file" >"$log" 2>&1 ||
  { cat "$log" >&2; die "cmake/patches/kokkos-3.4.1-cuda13.patch does not apply to $deps/src/kokkos (log: $log)"; }

echo "== building Kokkos (kokkos-cuda) into $prefix (log: $log)"
start=$(date +%s)
if ! { cmake -S "$src" -B "$build" -G Ninja -DCMAKE_INSTALL_PREFIX="$prefix" \
         -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" -DCMAKE_CXX_FLAGS="$arch_flag" \
         "${options[@]}" &&
       cmake --build "$build" --parallel "$(nproc)" &&
       cmake --install "$build"; } >>"$log" 2>&1; then
  tail -n 30 "$log" >&2
  die "building Kokkos with CUDA failed (full log: $log)"
fi
rm -rf "$build"
echo "$stamp_text" >"$prefix/.granshock-stamp"
echo "== Kokkos (kokkos-cuda) built in $(( $(date +%s) - start )) s: $prefix"

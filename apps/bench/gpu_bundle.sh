#!/usr/bin/env bash
# Packs a CUDA build for a GPU machine that has the NVIDIA driver but not the Debian
# packages granshock links (HDF5, Open MPI, fmt, ...): docs/cuda.md, "The device check".
# The archive holds build-cuda/'s granshock, the gas benchmark and the test programs named,
# stripped, and build-cuda/runtime-libs/ with every shared library they load that the C
# library does not provide; the C++ runtime they were built with goes to
# runtime-libs/cxx-runtime/, used only where the machine's own is older. The driver
# (libcuda) is never packed: it must be the machine's own.
#
# Usage: apps/bench/gpu_bundle.sh [TEST_PROGRAM...]   (default: test_unit test_physics)
# Writes build-cuda/gpu-bundle.tar.gz; unpack it in the repository's root on the GPU
# machine and run GRANSHOCK_GPU_CHECK_PREBUILT=1 apps/bench/gpu_check.sh there.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$repo/build-cuda
me=gpu_bundle.sh
die() { echo "$me: $*" >&2; exit 1; }

programs=(apps/granshock/granshock apps/bench/granshock_bench_gas)
for t in "${@:-test_unit test_physics}"; do
  for name in $t; do programs+=("tests/$name"); done
done
for p in "${programs[@]}"; do
  [ -x "$build/$p" ] || die "$build/$p is missing: build it first (cmake/build_cuda.sh)"
done

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/build-cuda/runtime-libs/cxx-runtime"
for p in "${programs[@]}"; do
  mkdir -p "$stage/build-cuda/$(dirname "$p")"
  strip --strip-unneeded -o "$stage/build-cuda/$p" "$build/$p"
done
# Every library the programs load, by the loader's own resolution; the C library's
# family and the driver stay the machine's.
ldd "${programs[@]/#/$build/}" | awk '/=> \// {print $1, $3}' | sort -u |
  while read -r name path; do
    case $name in
      libc.so* | libm.so* | libdl.so* | librt.so* | libpthread.so* | libresolv.so* | \
        libutil.so* | libanl.so* | libnsl.so* | libmvec.so* | ld-linux* | \
        libcuda.so* | libnvidia*) ;;
      libstdc++.so* | libgcc_s.so*) cp -L "$path" "$stage/build-cuda/runtime-libs/cxx-runtime/$name" ;;
      *) cp -L "$path" "$stage/build-cuda/runtime-libs/$name" ;;
    esac
  done
tar -C "$stage" -czf "$build/gpu-bundle.tar.gz" build-cuda
echo "$me: $build/gpu-bundle.tar.gz, $(du -h "$build/gpu-bundle.tar.gz" | cut -f1):" \
  "${programs[*]} and $(find "$stage/build-cuda/runtime-libs" -type f | wc -l) libraries"

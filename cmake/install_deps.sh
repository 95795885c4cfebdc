#!/usr/bin/env bash
# Installs everything granshock needs on a Debian 12 machine, idempotently:
#   1. Debian packages (needs root; skipped when all are already installed),
#   2. Kokkos with the OpenMP + Serial backends, built from Debian's own trilinos
#      source package into a local prefix (Debian's binary Kokkos is Serial-only).
# A second call finds everything in place and returns in seconds.
#
# Usage: cmake/install_deps.sh
# Environment: GRANSHOCK_DEPS (default: <repo>/.deps) holds sources and prefixes.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps=${GRANSHOCK_DEPS:-$repo/.deps}
if [ $# -gt 0 ]; then
  echo "install_deps.sh: unexpected argument '$1' (it takes none)" >&2
  exit 2
fi

packages=(
  build-essential cmake ninja-build pkg-config git ca-certificates xz-utils dpkg-dev
  clang-format
  libeigen3-dev
  libopenmpi-dev openmpi-bin libhdf5-openmpi-dev hdf5-tools
  libgtest-dev libgmock-dev libbenchmark-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  # The Python reader (python/granshock, docs/python.md) and the thermo table (docs/output_format.md).
  python3-matplotlib python3-h5py python3-pandas
  # ParaView's pvbatch and an X server without a screen, for io.paraview_opens_outputs
  # (docs/output_format.md, "What ParaView shows"): about 140 MB to download, 800 MB installed.
  python3-paraview xvfb xauth
  # ps and pgrep, for the command-line tests that check no process is left behind
  # (tests/cli/gpu_study_mps.sh).
  procps
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing Debian packages: ${missing[*]}"
  mkdir -p "$deps"
  if ! { as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq &&
         as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
           --no-install-recommends "${missing[@]}"; } >"$deps/apt.log" 2>&1; then
    tail -n 30 "$deps/apt.log" >&2
    echo "install_deps.sh: apt-get failed (full log: $deps/apt.log)" >&2
    exit 1
  fi
else
  echo "== Debian packages: all present"
fi

# --- Kokkos from Debian's trilinos source package ----------------------------------
kokkos_src=$deps/src/kokkos
fetch_kokkos_source() {
  [ -f "$kokkos_src/CMakeLists.txt" ] && return 0
  local src_list=/etc/apt/sources.list.d/granshock-deb-src.sources
  if [ ! -f "$src_list" ]; then
    echo "== enabling Debian source packages ($src_list)"
    if [ -f /etc/apt/sources.list.d/debian.sources ]; then
      sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources
    else  # one-line style sources.list
      grep -h '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' |
        awk '{print "Types: deb-src\nURIs: "$2"\nSuites: "$3"\nComponents: "$4"\n"}'
    fi | as_root tee "$src_list" >/dev/null
    as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq >/dev/null
  fi
  mkdir -p "$deps/src/download"
  (cd "$deps/src/download" && ls trilinos_*.orig.tar.* >/dev/null 2>&1 ||
     apt-get source --download-only trilinos >/dev/null)
  local tarball
  tarball=$(ls "$deps"/src/download/trilinos_*.orig.tar.* | head -n 1)
  echo "== unpacking Kokkos from $(basename "$tarball")"
  rm -rf "$deps/src/unpack" && mkdir -p "$deps/src/unpack"
  tar -xf "$tarball" -C "$deps/src/unpack" --wildcards '*/packages/kokkos/*'
  rm -rf "$kokkos_src"
  mv "$deps"/src/unpack/*/packages/kokkos "$kokkos_src"
  rm -rf "$deps/src/unpack" "$deps/src/download"  # the 160 MB trilinos tarball
}

build_kokkos() { # name, extra cmake args...
  local name=$1; shift
  local prefix=$deps/$name
  if [ -f "$prefix/.granshock-stamp" ]; then
    echo "== Kokkos ($name): present in $prefix"
    return 0
  fi
  fetch_kokkos_source
  echo "== building Kokkos ($name) into $prefix"
  rm -rf "$deps/build-$name"
  cmake -S "$kokkos_src" -B "$deps/build-$name" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_CXX_STANDARD=17 -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON \
    -DKokkos_ENABLE_TESTS=OFF -DKokkos_ENABLE_EXAMPLES=OFF "$@" >/dev/null
  cmake --build "$deps/build-$name" --parallel "$(nproc)" >"$deps/build-$name.log" 2>&1 ||
    { tail -n 30 "$deps/build-$name.log" >&2; exit 1; }
  cmake --install "$deps/build-$name" >/dev/null
  rm -rf "$deps/build-$name"
  touch "$prefix/.granshock-stamp"
}

build_kokkos kokkos-openmp

echo "== dependencies ready (Kokkos prefix: $deps/kokkos-openmp)"

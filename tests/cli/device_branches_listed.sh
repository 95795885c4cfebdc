#!/usr/bin/env bash
# Every place where granshock's code chooses between a host and a device way of doing
# something is listed in docs/cuda.md ("Branch points"), so that the device-path build
# (GRANSHOCK_DEVICE_PATHS) and a first GPU run know what they test. A branch asks the one
# predicate of kernels/device/backends.hpp through its KernelPaths tag (`Paths::host`), or
# the host-accessibility behind it; this test fails when a source line that does so is not
# in the table (counted per file), when the table lists more than the sources hold, and
# when Kokkos' SpaceAccessibility is asked anywhere but backends.hpp (ask the predicate),
# and when Kokkos' create_mirror* is called anywhere but device/host_mirror.hpp.
# Comments are ignored; the tests, which force one way or the other on purpose, are not
# scanned. Usage: device_branches_listed.sh SOURCE_DIR
set -euo pipefail
root=$1
doc=$root/docs/cuda.md
cd "$root"
fail=0

definition=kernels/device/backends.hpp
mirrors=kernels/device/host_mirror.hpp
branch='Paths::host|host_accessible<|uses_host_paths<|SpaceAccessibility|__CUDA_ARCH__'

# One pass over the sources (comments stripped): per file with any, the lines that branch
# on host or device, that ask SpaceAccessibility, and that call create_mirror*.
mapfile -t sources < <(find kernels core cases analysis io parallel apps -type f \
  \( -name '*.hpp' -o -name '*.cpp' -o -name '*.inl' -o -name '*.h' \) | sort)
counts=$(awk -v branch="$branch" '
  { line = $0; sub(/\/\/.*$/, "", line)
    if (line ~ branch) b[FILENAME]++
    if (line ~ /SpaceAccessibility/) a[FILENAME]++
    if (line ~ /create_mirror/) m[FILENAME]++ }
  END { for (f in b) seen[f] = 1; for (f in m) seen[f] = 1
        for (f in seen) print f, b[f] + 0, a[f] + 0, m[f] + 0 }' "${sources[@]}" | sort)

# The table's rows: the first cell names the file in backquotes.
# shellcheck disable=SC2016 # backquotes of Markdown, not of the shell
listed=$(sed -n '/^## Branch points/,/^## /p' "$doc" | grep -E '^\| *`[^`]+`' |
  sed -E 's/^\| *`([^`]+)`.*/\1/' | sort | uniq -c | awk '{print $2, $1}')
[ -n "$listed" ] || { echo "docs/cuda.md has no \"## Branch points\" table" >&2; exit 1; }

total=0
while read -r f found asks mirrored; do
  if [ -z "$f" ] || [ "$f" = "$definition" ]; then continue; fi
  if [ "$asks" -gt 0 ]; then
    echo "$f: asks Kokkos::SpaceAccessibility itself; ask the predicate instead" \
      "(uses_host_paths, or Paths::host in a kernel: $definition) so that GRANSHOCK_DEVICE_PATHS flips it" >&2
    fail=1
  fi
  # Kokkos' mirrors are a host-or-device choice too (on a host backend the View itself);
  # device/host_mirror.hpp makes it by the paths.
  if [ "$mirrored" -gt 0 ] && [ "$f" != "$mirrors" ]; then
    echo "$f: calls Kokkos' create_mirror*; use host_mirror, host_copy or device_copy" \
      "($mirrors) so that GRANSHOCK_DEVICE_PATHS makes separate copies as on a GPU" >&2
    fail=1
  fi
  [ "$found" -eq 0 ] && continue
  total=$((total + found))
  want=$(echo "$listed" | awk -v f="$f" '$1 == f {print $2}')
  if [ "${want:-0}" -ne "$found" ]; then
    echo "$f: $found line(s) branch on host or device, docs/cuda.md (\"Branch points\") lists ${want:-0}:" >&2
    sed -e 's://.*$::' "$f" | grep -nE "$branch" >&2 || true
    fail=1
  fi
done <<<"$counts"
while read -r f want; do
  if ! echo "$counts" | awk -v f="$f" '$1 == f && $2 > 0 {ok = 1} END {exit !ok}'; then
    echo "docs/cuda.md lists $want branch point(s) in $f, which has none" >&2
    fail=1
  fi
done <<<"$listed"

[ "$fail" -eq 0 ] || exit 1
echo "$total branch points, each listed in docs/cuda.md"

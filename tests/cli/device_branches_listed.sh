#!/usr/bin/env bash
# Every place where granshock's code chooses between a host and a device way of doing
# something is listed in docs/cuda.md ("Branch points"), so that the device-path build
# (GRANSHOCK_DEVICE_PATHS) and a first GPU run know what they test. A branch asks the one
# predicate of kernels/device/backends.hpp through its KernelPaths tag (`Paths::host`), or
# the host-accessibility behind it; this test fails when a source line that does so is not
# in the table (counted per file), when the table lists more than the sources hold, and
# when Kokkos' SpaceAccessibility is asked anywhere but backends.hpp (ask the predicate).
# Comments are ignored; the tests, which force one way or the other on purpose, are not
# scanned. Usage: device_branches_listed.sh SOURCE_DIR
set -euo pipefail
root=$1
doc=$root/docs/cuda.md
cd "$root"
fail=0

sources=$(find kernels core cases analysis io parallel apps -type f \
  \( -name '*.hpp' -o -name '*.cpp' -o -name '*.inl' -o -name '*.h' \) | sort)
definition=kernels/device/backends.hpp

# Source lines (comments stripped) that branch on host or device.
branch_lines() {
  sed -e 's://.*$::' "$1" |
    grep -cE 'Paths::host|host_accessible<|uses_host_paths<|SpaceAccessibility|__CUDA_ARCH__' || true
}

for f in $sources; do
  [ "$f" = "$definition" ] && continue
  if sed -e 's://.*$::' "$f" | grep -q 'SpaceAccessibility'; then
    echo "$f: asks Kokkos::SpaceAccessibility itself; branch on the KernelPaths tag" \
      "(Paths::host, $definition) so that GRANSHOCK_DEVICE_PATHS flips it" >&2
    fail=1
  fi
done

# The table's rows: the first cell names the file in backquotes.
# shellcheck disable=SC2016 # backquotes of Markdown, not of the shell
listed=$(sed -n '/^## Branch points/,/^## /p' "$doc" | grep -E '^\| *`[^`]+`' |
  sed -E 's/^\| *`([^`]+)`.*/\1/' | sort | uniq -c | awk '{print $2, $1}')
[ -n "$listed" ] || { echo "docs/cuda.md has no \"## Branch points\" table" >&2; exit 1; }

total=0
for f in $sources; do
  [ "$f" = "$definition" ] && continue
  found=$(branch_lines "$f")
  [ "$found" -eq 0 ] && continue
  total=$((total + found))
  want=$(echo "$listed" | awk -v f="$f" '$1 == f {print $2}')
  if [ "${want:-0}" -ne "$found" ]; then
    echo "$f: $found line(s) branch on host or device, docs/cuda.md (\"Branch points\") lists ${want:-0}:" >&2
    sed -e 's://.*$::' "$f" | grep -nE 'Paths::host|host_accessible<|uses_host_paths<|SpaceAccessibility|__CUDA_ARCH__' >&2 || true
    fail=1
  fi
done
while read -r f want; do
  if [ ! -f "$f" ] || [ "$(branch_lines "$f")" -eq 0 ]; then
    echo "docs/cuda.md lists $want branch point(s) in $f, which has none" >&2
    fail=1
  fi
done <<<"$listed"

[ "$fail" -eq 0 ] || exit 1
echo "$total branch points, each listed in docs/cuda.md"

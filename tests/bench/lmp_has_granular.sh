#!/usr/bin/env bash
# apps/bench/lammps/common.sh's lmp_has_granular against stand-in LAMMPS binaries whose
# help text, like the real one's, runs far past a pipe's buffer after the package list:
# it must find GRANULAR under `set -o pipefail` (install_lammps.sh once piped `lmp -h` into
# `grep -q` there and reported Debian's lammps as lacking the package) and must not find
# it where the list lacks it.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/../../apps/bench/lammps/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fake_lmp() {  # path, package list
  cat >"$1" <<FAKE
#!/usr/bin/env bash
echo "Installed packages:"
echo
echo "$2"
for k in \$(seq 1 20000); do echo "pair style number \$k of the long list that follows"; done
FAKE
  chmod +x "$1"
}
fake_lmp "$work/with" "ASPHERE BODY CLASS2 COLLOID GRANULAR KSPACE MANYBODY"
fake_lmp "$work/without" "ASPHERE BODY CLASS2 COLLOID GRANULARITY KSPACE MANYBODY"

lmp_has_granular "$work/with" || { echo "FAIL: GRANULAR not found in the long help text" >&2; exit 1; }
if lmp_has_granular "$work/without"; then
  echo "FAIL: GRANULAR found where only GRANULARITY is listed" >&2
  exit 1
fi
echo "lmp_has_granular: found in a long help text, not found where missing"

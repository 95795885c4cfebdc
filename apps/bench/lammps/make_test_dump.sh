#!/usr/bin/env bash
# Writes the LAMMPS dump that the tests of `granshock fields --from-dump` read
# (tests/fields/dump/small_bow_shock.dump; docs/fields.md, "Fields from LAMMPS or LIGGGHTS
# dumps"): granshock runs small_bow_shock.toml to t = 0.06 s, then LAMMPS continues from
# that state with bench_bow_shock.sh for 3750 steps of 2e-7 s on one rank, writing
# `dump custom` frames id type x y z vx vy vz every 250 steps (16 frames, ~220 particles,
# ~180 kB). dump_map.toml is the map for it. Needs LAMMPS (install_lammps.sh) and a built
# granshock (GRANSHOCK, default <repo>/build/apps/granshock/granshock).
#
# Usage: make_test_dump.sh OUT.dump
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/common.sh"
if (($# != 1)); then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' >&2
  exit 2
fi
out=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} OMP_PROC_BIND=false \
  run_nice "$(find_granshock)" run "$here/small_bow_shock.toml" --out "$work/state" --quiet \
  --no-figures >&2
rm -f "$out"
STATE=$work/state DUMP=$out DUMP_EVERY=250 "$here/bench_bow_shock.sh" 1 3750 >/dev/null

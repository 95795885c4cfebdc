#!/usr/bin/env bash
# Writes the test dump again with LAMMPS (apps/bench/lammps/make_test_dump.sh) and checks
# that it has the committed dump's frames: the same timesteps and atoms per frame
# (tests/fields/dump/README.md), and that `granshock fields --from-dump` reads it.
# Exit 77 (skipped) without LAMMPS. Usage: from_dump_regenerated.sh GRANSHOCK SOURCE_DIR
set -euo pipefail
granshock=$1 src=$2
command -v lmp >/dev/null || command -v lmp_mpi >/dev/null || command -v lmp_serial >/dev/null ||
  exit 77
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
NICE=0 GRANSHOCK=$granshock "$src/apps/bench/lammps/make_test_dump.sh" "$tmp/new.dump"
frames() { grep -A1 -e '^ITEM: TIMESTEP' -e '^ITEM: NUMBER OF ATOMS' "$1"; }
diff <(frames "$src/tests/fields/dump/small_bow_shock.dump") <(frames "$tmp/new.dump")
"$granshock" fields --from-dump lammps "$tmp/new.dump" --map "$src/apps/bench/lammps/dump_map.toml" \
  --out "$tmp/out" --no-figures
grep -q '"dump_frames_used": 16' "$tmp/out/summary.json"
echo PASS

#!/usr/bin/env bash
# LAMMPS on a granshock scene with granshock's inflow (lammps_inflow.py), for the
# cross-check (README.md here). Writes WORK/run.in, inflow.data, run.log, frames.dump
# (`dump custom` id type x y z vx vy vz of the particles at y >= 0, every DUMP_EVERY s
# of the production window) and wall_seconds.
#
# Usage: run_lammps.sh RANKS WORK SCENE.toml [--set KEY=VALUE ...]
# Environment: SIGMA (m/s: overrides inflow.sigma, e.g. the sigma granshock calibrated for
#   inflow.mach, from its summary.json), DUMP_EVERY (s, default 5e-4), GRANSHOCK, LMP,
#   NICE (default 10), REFILL_BLOCK (d: a short reservoir refilled with blocks of that
#   length, lammps_inflow.py --refill-block; default one reservoir for the whole run),
#   SEED (the placement and velocity seed, default 1).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/../../../apps/bench/lammps/common.sh"
if (($# < 3)); then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' >&2
  exit 2
fi
ranks=$1 work=$2 scene=$3
shift 3
lmp=$(find_lmp)
lmp_has_granular "$lmp" || { echo "$lmp has no GRANULAR package" >&2; exit 1; }
mkdir -p "$work"
# The scene as granshock resolves it (SI units, defaults filled in), --set options included.
"$(find_granshock)" run "$scene" --dry-run "$@" | grep -v '^#' > "$work/scene_resolved.toml"
"$here/lammps_inflow.py" "$work/scene_resolved.toml" "$work" --ranks "$ranks" \
  --dump-every "${DUMP_EVERY:-5e-4}" ${SIGMA:+--sigma "$SIGMA"} ${REFILL_BLOCK:+--refill-block "$REFILL_BLOCK"} ${SEED:+--seed "$SEED"}
start=$(date +%s.%N)
(cd "$work" && lammps_mpirun "$ranks" "$lmp" -in run.in -log run.log -screen none)
end=$(date +%s.%N)
grep -q CROSS_CHECK_DONE "$work/run.log" || { echo "LAMMPS did not finish: $work/run.log" >&2; exit 1; }
/usr/bin/python3 -c "print(f'{$end - $start:.0f}')" > "$work/wall_seconds"
echo "LAMMPS $(lmp_version "$lmp"), $ranks rank(s): $(cat "$work/wall_seconds") s wall" >&2

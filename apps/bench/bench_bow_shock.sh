#!/usr/bin/env bash
# granshock's particle-steps per second on the default scene (scenes/default.toml), timed
# the way apps/bench/lammps/bench_bow_shock.sh times LAMMPS: STEPS steps from the state at
# t = 0.1 s, with field sampling on (every 50 steps, as the scene says) and the scene's
# outputs. So the two can be run side by side:
#
#   apps/bench/bench_bow_shock.sh 20000 && apps/bench/lammps/bench_bow_shock.sh 2 20000
#
# How: the scene runs to WARMUP_STEPS and stops with a checkpoint (--stop-after-steps),
# then `--resume` runs the STEPS timed steps; summary.json's particle_steps_per_second is
# the rate of that leg alone (cases/bow_shock/run_summary.cpp: particle-steps summed over
# the solver's advance() calls / the leg's wall time, inflow, sampling and output
# included). Production (field sampling) starts with the timed leg. WARMUP_STEPS = 0 times
# a single run from the empty-of-shock initial state instead.
#
# Usage: bench_bow_shock.sh [STEPS] [WARMUP_STEPS]   (defaults 20000, 500000 = 0.1 s)
# Environment: GRANSHOCK (binary, default <repo>/build/apps/granshock/granshock), THREADS
#   (OpenMP threads, default 2), NICE (default 10), KEEP (a run directory to keep).
# Output: progress on stderr, the particle-steps/s alone on the last line of stdout.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/lammps/common.sh"  # find_granshock, run_nice, timed_leg_times
steps=${1:-20000}
warmup=${2:-500000}
scene=$root/scenes/default.toml
granshock=$(find_granshock)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=${KEEP:-$work/run}
# OpenMP threads wait for the next parallel region by spinning (OMP_WAIT_POLICY=active,
# the default for short waits): granshock launches one region per step, and with
# passive waiting (a sleep and a wake-up per region) the default scene ran at half the
# rate (docs/benchmarks.md). Set OMP_WAIT_POLICY=passive on a machine shared with other
# work, where a spinning thread that loses its core stalls every barrier.
export OMP_NUM_THREADS=${THREADS:-2} OMP_PROC_BIND=${OMP_PROC_BIND:-false} \
  OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-active}

timed_leg_times "$scene" "$warmup" "$steps"  # sets dt and times
echo "granshock $granshock, $OMP_NUM_THREADS thread(s): $steps steps timed after $warmup" \
  "(dt = $dt s)" >&2
if ((warmup > 0)); then
  run_nice "$granshock" run "$scene" --out "$out" --overwrite --quiet "${times[@]}" \
    --stop-after-steps "$warmup" >&2
  run_nice "$granshock" run "$scene" --out "$out" --resume --quiet "${times[@]}" >&2
else
  run_nice "$granshock" run "$scene" --out "$out" --overwrite --quiet "${times[@]}" >&2
fi
/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"particles at the end {s['particles_final']}, {s['list_builds']} list builds in all, "
      f"variant {s['variant']}, {s['threads']} threads", file=sys.stderr)
print(f"{s['particle_steps_per_second']:.4g}")
PY

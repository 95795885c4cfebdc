#!/usr/bin/env bash
# Old against new in the same run: the gas benchmark and the default scene (shortened),
# each run by two builds in alternation, REPEATS times, on an otherwise idle machine.
# Prints the median particle-steps/s of each build and the ratio new / old per case.
# A restructuring must not be slower: ratio >= 0.98 (docs/benchmarks.md).
#
# Usage: compare_builds.sh OLD_BUILD_DIR NEW_BUILD_DIR
# Environment: REPEATS (default 5), THREADS (default 2), N (gas particles, default 32000),
#   SCENE_DURATION (default 0.05 s simulated of scenes/default.toml).
set -euo pipefail
old=$1 new=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
scene=$here/../../scenes/default.toml
repeats=${REPEATS:-5}
threads=${THREADS:-2}
n=${N:-32000}
duration=${SCENE_DURATION:-0.05}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# OpenMP threads wait for the next parallel region by spinning (OMP_WAIT_POLICY=active,
# the default for short waits): granshock launches one region per step, and with
# passive waiting (a sleep and a wake-up per region) the default scene ran at half the
# rate (docs/benchmarks.md). Set OMP_WAIT_POLICY=passive on a machine shared with other
# work, where a spinning thread that loses its core stalls every barrier.
export OMP_NUM_THREADS=$threads OMP_PROC_BIND=${OMP_PROC_BIND:-false} \
  OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-active}

gas() {  # build phi -> particle-steps/s
  "$1/apps/bench/granshock_bench_gas" --particles "$n" --phi "$2" --repeats 1 \
    --min-seconds 2 --json "$work/gas.json" >/dev/null 2>&1
  /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results'][0]['median'])" \
    "$work/gas.json"
}

scene_rate() {  # build -> particle-steps/s of the default scene
  rm -rf "$work/run"
  "$1/apps/granshock/granshock" run "$scene" --out "$work/run" --quiet \
    --set time.duration="$duration" --set time.production_start=0 >/dev/null 2>&1
  /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['particle_steps_per_second'])" \
    "$work/run/summary.json"
}

declare -A rates
for ((r = 1; r <= repeats; ++r)); do
  for build in old new; do
    dir=$old
    [[ $build == new ]] && dir=$new
    rates[$build,gas0.1]+="$(gas "$dir" 0.1) "
    rates[$build,gas0.5]+="$(gas "$dir" 0.5) "
    rates[$build,scene]+="$(scene_rate "$dir") "
  done
done

median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
printf "| case | old (particle-steps/s) | new | new / old |\n|---|---|---|---|\n"
for c in gas0.1 gas0.5 scene; do
  o=$(echo "${rates[old,$c]}" | median)
  w=$(echo "${rates[new,$c]}" | median)
  label=$c
  [[ $c == gas* ]] && label="gas N=$n phi=${c#gas}"
  [[ $c == scene ]] && label="default scene, ${duration} s"
  awk -v l="$label" -v o="$o" -v w="$w" 'BEGIN {printf "| %s | %.4g | %.4g | %.3f |\n", l, o, w, w / o}'
done
echo "(medians of $repeats alternating repeats, $threads threads)"

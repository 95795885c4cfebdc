#!/usr/bin/env bash
# granshock beside busy processes (docs/benchmarks.md, "A busy machine"): the default scene
# for DURATION of simulated time on 2 threads with the backend switch on (the default) and
# off, and on 1 thread, each beside 0, 1 and 2 busy single-threaded processes (`yes`), and
# beside a second granshock on one thread. With a reference binary or source (the
# hand-written OpenMP gas step, docs/benchmarks.md), its gas rate (phi 0.1, 32k) on 2 and
# 1 threads in the same conditions. Prints one table of medians over REPEATS runs, with
# the CPU model; each rate is particle-steps per second of the run's own timing
# (summary.json: particle_steps_per_second; the reference's RESULT line).
#
# Usage: contention.sh [REFERENCE.cpp|REFERENCE_BINARY]
# Environment: GRANSHOCK (default <repo>/build/apps/granshock/granshock), DURATION
#   (default 0.02 s simulated), REPEATS (default 3), LOADS (default "0 1 2 g": busy `yes`
#   processes, g = one granshock), CONFIGS (default "2:auto 2:off 1:off"), OLD_GRANSHOCK
#   (another build: its 2:auto run beside each of granshock's, for old against new).
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
granshock=${GRANSHOCK:-$root/build/apps/granshock/granshock}
duration=${DURATION:-0.02}
repeats=${REPEATS:-3}
loads=${LOADS:-"0 1 2 g"}
configs=${CONFIGS:-"2:auto 2:off 1:off"}
reference=${1:-}
production=$(awk -v d="$duration" 'BEGIN { print d / 2 }')  # sampling in the second half
work=$(mktemp -d)
busy=()
stop_load() {
  for p in "${busy[@]}"; do kill "$p" 2>/dev/null; done
  wait "${busy[@]}" 2>/dev/null
  busy=()
}
trap 'stop_load; rm -rf "$work"' EXIT
[[ -x $granshock ]] || { echo "no $granshock: build granshock first" >&2; exit 2; }
if [[ $reference == *.cpp ]]; then
  g++ -O3 -march=native -fopenmp -std=c++17 -o "$work/reference" "$reference" || exit 2
  reference=$work/reference
fi
export OMP_PROC_BIND=false SOL_CACHE=$work

start_load() {  # LOAD: 0, N busy `yes`, or g (a granshock on one thread, run after run)
  case $1 in
    g)
      (while :; do
        OMP_NUM_THREADS=1 "$granshock" run "$root/scenes/default.toml" --quiet \
          --set time.duration=0.05 --set time.production_start=0.025 --backend-switch off \
          --out "$work/load" --overwrite >/dev/null 2>&1
      done) &
      busy+=($!)
      ;;
    *)
      for ((k = 0; k < $1; ++k)); do
        yes >/dev/null &
        busy+=($!)
      done
      ;;
  esac
  sleep 1
}

granshock_rate() {  # THREADS SWITCH [BINARY] -> "rate wall moves skipped" of one run
  OMP_NUM_THREADS=$1 "${3:-$granshock}" run "$root/scenes/default.toml" --quiet \
    --set time.duration="$duration" --set time.production_start="$production" \
    --backend-switch "$2" --out "$work/run" --overwrite --no-figures \
    >/dev/null 2>"$work/err" || { echo "nan nan nan nan"; return; }
  /usr/bin/python3 - "$work/run/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
b = s.get("backend_switch", {})
print("%.3g %.1f %d %s" % (s["particle_steps_per_second"], s["wall_seconds"], b.get("moves", 0),
                           b.get("tries_skipped_busy", "-")))
PY
}

reference_rate() {  # THREADS -> rate
  OMP_NUM_THREADS=$1 "$reference" bench vl_1p 0.1 32000 2 1 2>/dev/null |
    awk '/^RESULT/ { for (k = 1; k <= NF; ++k) if ($k == "median") print $(k + 1) }'
}

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) CPUs;" \
  "default scene, $duration s simulated; medians of $repeats runs"
echo
echo "| load | granshock threads:switch | particle-steps/s | wall s | moves | tries skipped |"
echo "|---|---|---|---|---|---|"
for load in $loads; do
  start_load "$load"
  label=$([[ $load == g ]] && echo "1 granshock" || echo "$load yes")
  runs=()
  [[ -n ${OLD_GRANSHOCK:-} ]] && runs+=("old 2:auto")
  for config in $configs; do runs+=("new $config"); done
  for run in "${runs[@]}"; do
    build=${run%% *} config=${run#* }
    threads=${config%%:*} switch=${config##*:}
    binary=$granshock name=$config
    [[ $build == old ]] && binary=$OLD_GRANSHOCK name="$config (OLD_GRANSHOCK)"
    rates="" walls="" moves="" skips=""
    for ((r = 0; r < repeats; ++r)); do
      read -r rate wall move skip < <(granshock_rate "$threads" "$switch" "$binary")
      rates+=" $rate" walls+=" $wall" moves+=" $move" skips+=" $skip"
    done
    echo "| $label | $name | $(echo "$rates" | median) | $(echo "$walls" | median) | $(echo "$moves" | median) | $(echo "$skips" | median) |"
  done
  if [[ -n $reference ]]; then
    for threads in 2 1; do
      rates=""
      for ((r = 0; r < repeats; ++r)); do rates+=" $(reference_rate "$threads")"; done
      echo "| $label | reference vl_1p gas 32k, $threads threads | $(echo "$rates" | median) | | |"
    done
  fi
  stop_load
done

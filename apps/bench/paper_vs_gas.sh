#!/usr/bin/env bash
# A paper case against granshock's own gas step at the same particle count and solid
# fraction (docs/benchmarks.md, "The paper case against the gas at the same N"):
# scenes/paper/d50_u1000.toml for DURATION of simulated time with the inflow's Mach number
# taken at insertion and production from t = 0 (31,600 particles), and
# granshock_bench_gas --particles 31600 --phi 0.1 --sigma 0.15 --placement random, in ROUNDS
# alternating
# rounds, on each thread count of THREADS, beside LOAD busy single-threaded processes
# (`yes`). Prints each round's two rates (particle-steps per second: summary.json's time
# loop, the gas table's median) and their ratio, then the median ratio, with the CPU model.
#
# With REFERENCE (the hand-written reference step's source or binary, docs/benchmarks.md)
# the second column is the reference's vl_1p gas at 32,000 particles, phi 0.1, sigma 0.15
# instead of granshock's own (the issue's "paper case against the reference").
#
# Usage: paper_vs_gas.sh
# Environment: GRANSHOCK, BENCH_GAS (default: build/apps/...), DURATION (default 0.05 s
#   simulated = 100,000 steps), ROUNDS (default 3), THREADS (default "1 2"), LOAD (default 0),
#   REFERENCE (default: none), PLACEMENT (the gas's start, default random: a lattice start
#   at phi 0.1 leaves the lists nearly empty, docs/benchmarks.md, "The paper case against a
#   random gas").
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
granshock=${GRANSHOCK:-$root/build/apps/granshock/granshock}
bench_gas=${BENCH_GAS:-$root/build/apps/bench/granshock_bench_gas}
duration=${DURATION:-0.05}
rounds=${ROUNDS:-3}
threads_list=${THREADS:-"1 2"}
load=${LOAD:-0}
work=$(mktemp -d)
busy=()
trap 'for p in "${busy[@]}"; do kill "$p" 2>/dev/null; done; rm -rf "$work"' EXIT
for b in "$granshock" "$bench_gas"; do
  [[ -x $b ]] || { echo "paper_vs_gas.sh: no $b: build granshock first" >&2; exit 2; }
done
export OMP_PROC_BIND=false
reference=${REFERENCE:-}
if [[ $reference == *.cpp ]]; then
  g++ -O3 -march=native -fopenmp -std=c++17 -o "$work/reference" "$reference"
  reference=$work/reference
fi

paper_rate() {  # THREADS -> particle-steps/s of the time loop
  OMP_NUM_THREADS=$1 "$granshock" run "$root/scenes/paper/d50_u1000.toml" --quiet \
    --set time.duration="$duration" --set time.production_start=0 \
    --set 'inflow.mach_at="inserted"' --out "$work/run" --overwrite --no-figures \
    >/dev/null 2>"$work/err" || { echo nan; return; }
  # The run's files are still being written back by the kernel; that took up to a third of
  # the next 2-second measurement's speed (2026-12-06).
  sync
  /usr/bin/python3 -c 'import json,sys; print("%.4g" % json.load(open(sys.argv[1]))["particle_steps_per_second"])' \
    "$work/run/summary.json"
}

gas_rate() {  # THREADS -> the gas table's median rate, or the reference's
  if [[ -n $reference ]]; then
    OMP_NUM_THREADS=$1 OMP_PROC_BIND=close OMP_PLACES=cores SOL_CACHE=$work \
      "$reference" bench vl_1p 0.1 32000 2 1 2>/dev/null |
      awk '/^RESULT/ { for (k = 1; k <= NF; ++k) if ($k == "median") print $(k + 1) }'
    return
  fi
  OMP_NUM_THREADS=$1 "$bench_gas" --particles 31600 --phi 0.1 --sigma 0.15 \
    --placement "${PLACEMENT:-random}" 2>/dev/null |
    awk -F'|' '/^\| 0.1 \|/ { gsub(/ /, "", $6); print $6; exit }'
}

for ((k = 0; k < load; ++k)); do
  yes >/dev/null &
  busy+=($!)
done
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) CPUs;" \
  "d50_u1000 for $duration s simulated against the gas at 31,600, phi 0.1;" \
  "$load busy processes beside; $rounds alternating rounds" \
  "${reference:+(second column: the reference step, vl_1p at 32,000, phi 0.1)}"
echo
echo "| threads | round | paper case | gas | ratio |"
echo "|---|---|---|---|---|"
for threads in $threads_list; do
  ratios=""
  for ((r = 1; r <= rounds; ++r)); do
    paper=$(paper_rate "$threads")
    gas=$(gas_rate "$threads")
    ratio=$(awk -v a="$paper" -v b="$gas" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "nan" }')
    ratios+=" $ratio"
    echo "| $threads | $r | $paper | $gas | $ratio |"
  done
  median=$(echo "$ratios" | tr ' ' '\n' | grep -v '^$' | sort -g |
    awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }')
  echo "| $threads | median | | | **$median** |"
done

#!/usr/bin/env bash
# Runs granshock_bench_gas over the standard matrix and prints one markdown table:
#   phi in {0.1, 0.5} x N in {5000, 32000, 250000, 2000000} x OpenMP threads in {1, 2},
# median particle-steps/s of 5 repeats, followed by the 2-thread / 1-thread speed-ups.
# About 3 minutes on a 2-core machine. Benchmarks are only meaningful on an otherwise
# idle machine: the load average is printed before and after each run, a repeat that
# did not get its cores' full CPU time is run again (granshock_bench_gas --retries), and
# the cases still disturbed are listed under the table.
#
# Environment (all optional):
#   BUILD_DIR       build directory (default: <repo>/build-bench; configured if absent)
#   BENCH           a granshock_bench_gas binary to run instead of building one
#   OUT_DIR         where the JSON results and table.md go (default: BUILD_DIR/bench_gas)
#   THREADS         thread counts to run (default: "1 2")
#   REPEATS         timed repeats per case (default: 5)
#   MIN_SECONDS     minimum seconds per repeat (default: 1.0)
#   MIN_SECONDS_2M  minimum seconds per repeat for N = 2000000 (default: 1.0)
#   PRECISION       double | single (default: double)
#   RETRIES         most disturbed repeats run again per case (default: 10)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${BUILD_DIR:-$root/build-bench}"
out="${OUT_DIR:-$build/bench_gas}"
threads_list="${THREADS:-1 2}"
repeats="${REPEATS:-5}"
min_seconds="${MIN_SECONDS:-1.0}"
min_seconds_2m="${MIN_SECONDS_2M:-1.0}"
precision="${PRECISION:-double}"
retries="${RETRIES:-10}"

if [[ -n "${BENCH:-}" ]]; then
  bench="$BENCH"
else
  if [[ ! -f "$build/CMakeCache.txt" ]]; then
    cmake -S "$root" -B "$build" -G Ninja >&2
  fi
  cmake --build "$build" --target granshock_bench_gas >&2
  bench="$build/apps/bench/granshock_bench_gas"
fi
mkdir -p "$out"

rows="$out/rows.md"
: > "$rows"
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }

run() {  # run THREADS TAG ARGS...
  local threads="$1" tag="$2"
  shift 2
  echo "# threads=$threads $tag: load average before: $(loadavg)" >&2
  OMP_NUM_THREADS="$threads" OMP_PROC_BIND=spread OMP_PLACES=threads \
    "$bench" --phi 0.1,0.5 --repeats "$repeats" --precision "$precision" --retries "$retries" \
    --json "$out/gas_${tag}_t${threads}.json" "$@" 2>&1 | tee "$out/gas_${tag}_t${threads}.log" >&2
  grep '^| [0-9]' "$out/gas_${tag}_t${threads}.log" >> "$rows"
}

start=$SECONDS
for t in $threads_list; do
  run "$t" small --particles 5000,32000,250000 --min-seconds "$min_seconds"
  run "$t" 2m --particles 2000000 --min-seconds "$min_seconds_2m"
done
echo "# load average after: $(loadavg); total $((SECONDS - start)) s" >&2

{
  echo "Median of $repeats repeats (each >= $min_seconds s; >= $min_seconds_2m s for N = 2M)," \
       "$precision precision, $(grep -m1 '^# granshock_bench_gas' "$out"/gas_small_t*.log | head -1 |
         sed -E 's/.*(Kokkos [0-9.]+, backend [A-Za-z]+).*/\1/')."
  echo
  echo "| phi | N | threads | variant | median p-steps/s | min | max | builds/1000 steps | contacts/particle |"
  echo "|---|---|---|---|---|---|---|---|---|"
  # Sort by phi, then N, then threads.
  sort -t'|' -k2,2g -k3,3n -k4,4n "$rows"
  echo
  echo "Speed-up, 2 threads over 1 thread (medians of the same run):"
  echo
  echo "| phi | N | 1 thread p-steps/s | 2 threads p-steps/s | speed-up |"
  echo "|---|---|---|---|---|"
  awk -F'|' '
    { gsub(/ /, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $4); gsub(/ /, "", $6)
      key = "| " $2 " | " $3; rate[key, $4] = $6; if (!(key in seen)) { seen[key] = 1; keys[++n] = key } }
    END {
      for (k = 1; k <= n; ++k) {
        key = keys[k]
        if (rate[key, 1] != "" && rate[key, 2] != "")
          printf "%s | %s | %s | %.2f |\n", key, rate[key, 1], rate[key, 2], rate[key, 2] / rate[key, 1]
      }
    }' "$rows" | sort -t'|' -k2,2g -k3,3n
  if grep -qh 'granshock_bench_gas: \(note\|warning\)' "$out"/gas_*.log; then
    echo
    echo "Repeats disturbed by other processes on the machine (see --min-cpu-share):"
    echo
    grep -h 'granshock_bench_gas: \(note\|warning\)' "$out"/gas_*.log | sed 's/^granshock_bench_gas: /- /'
  fi
} | tee "$out/table.md"

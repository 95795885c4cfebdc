#!/usr/bin/env bash
# Runs granshock_bench_gas over the standard matrix and prints one markdown table:
#   phi in {0.1, 0.5} x N in {5000, 32000, 250000, 2000000} x OpenMP threads in {1, 2},
# median particle-steps/s of 5 repeats, followed by the 2-thread / 1-thread speed-ups.
# About 2 minutes on an idle 2-core machine; at most about 8 with the defaults when
# every case has to be run twice (a busy machine).
#
# Benchmarks are only meaningful when nothing else runs on the cores. Each case is a
# separate run of a few seconds; a repeat that did not get its cores' full CPU time is
# run again (granshock_bench_gas --retries), and a case still disturbed after that is
# run again after a pause (CASE_ATTEMPTS). Cases disturbed in every attempt are listed
# under the table: their numbers measure the machine's load, not granshock.
#
# Environment (all optional):
#   BUILD_DIR       build directory (default: <repo>/build-bench; configured if absent)
#   BENCH           a granshock_bench_gas binary to run instead of building one
#   OUT_DIR         where the JSON results, logs and table.md go (default: BUILD_DIR/bench_gas)
#   THREADS         thread counts to run (default: "1 2")
#   REPEATS         timed repeats per case (default: 5)
#   MIN_SECONDS     minimum seconds per repeat (default: 1.0)
#   MIN_SECONDS_2M  minimum seconds per repeat for N = 2000000 (default: 1.0)
#   PRECISION       double | single (default: double)
#   RETRIES         most disturbed repeats run again within one attempt (default: 3)
#   CASE_ATTEMPTS   most attempts per case (default: 2)
#   PAUSE           seconds to wait before another attempt (default: 10)
#   WAIT_IDLE       before each attempt, wait up to this many seconds until the CPUs
#                   are >= 90% idle for 2 s (default: 0, do not wait)
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
retries="${RETRIES:-3}"
case_attempts="${CASE_ATTEMPTS:-2}"
pause="${PAUSE:-10}"
wait_idle="${WAIT_IDLE:-0}"
phis=(0.1 0.5)
sizes=(5000 32000 250000 2000000)

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
disturbed="$out/disturbed.txt"
: > "$rows"
: > "$disturbed"
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }

idle_percent() {  # share of idle CPU time over the next second, in percent
  local a b
  read -r -a a < <(grep '^cpu ' /proc/stat)
  sleep 1
  read -r -a b < <(grep '^cpu ' /proc/stat)
  local total=0 k
  for ((k = 1; k < ${#a[@]}; ++k)); do total=$((total + b[k] - a[k])); done
  echo $((total > 0 ? 100 * (b[4] - a[4]) / total : 100))
}

wait_for_idle() {  # gives up after WAIT_IDLE seconds
  local deadline=$((SECONDS + wait_idle)) quiet=0
  while ((SECONDS < deadline)); do
    if (($(idle_percent) >= 90)); then
      quiet=$((quiet + 1))
      if ((quiet >= 2)); then return 0; fi
    else
      quiet=0
    fi
  done
}

run_case() {  # run_case THREADS PHI N MIN_SECONDS
  local threads="$1" phi="$2" n="$3" seconds="$4"
  local tag="phi${phi}_n${n}_t${threads}" attempt
  for ((attempt = 1; attempt <= case_attempts; ++attempt)); do
    if ((wait_idle > 0)); then wait_for_idle; fi
    echo "# $tag attempt $attempt: load average before: $(loadavg)" >&2
    OMP_NUM_THREADS="$threads" OMP_PROC_BIND=spread OMP_PLACES=threads \
      "$bench" --phi "$phi" --particles "$n" --repeats "$repeats" --min-seconds "$seconds" \
      --precision "$precision" --retries "$retries" --json "$out/gas_$tag.json" \
      > "$out/gas_$tag.log" 2>&1
    grep -v '^# \|^|---\|^| phi' "$out/gas_$tag.log" >&2 || true
    if ! grep -q 'granshock_bench_gas: warning' "$out/gas_$tag.log"; then break; fi
    if ((attempt < case_attempts)); then sleep "$pause"; fi
  done
  grep '^| [0-9]' "$out/gas_$tag.log" >> "$rows"
  grep 'granshock_bench_gas: warning' "$out/gas_$tag.log" >> "$disturbed" || true
}

start=$SECONDS
for t in $threads_list; do
  for phi in "${phis[@]}"; do
    for n in "${sizes[@]}"; do
      seconds="$min_seconds"
      if ((n >= 2000000)); then seconds="$min_seconds_2m"; fi
      run_case "$t" "$phi" "$n" "$seconds"
    done
  done
done
echo "# load average after: $(loadavg); total $((SECONDS - start)) s" >&2

{
  header="$(grep -m1 '^# granshock_bench_gas' "$out"/gas_*.log | head -1 |
    sed -E 's/.*(Kokkos [0-9.]+, backend [A-Za-z]+).*/\1/')"
  echo "Median of $repeats repeats (each >= $min_seconds s; >= $min_seconds_2m s for N = 2M)," \
    "$precision precision, $header."
  echo
  echo "| phi | N | threads | variant | median p-steps/s | min | max | builds/1000 steps | contacts/particle | bytes/particle | growth (kB) |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
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
  if [[ -s "$disturbed" ]]; then
    echo
    echo "Cases disturbed by other processes in every attempt (their numbers are not valid):"
    echo
    sed 's/^granshock_bench_gas: warning: /- /' "$disturbed"
  fi
} | tee "$out/table.md"

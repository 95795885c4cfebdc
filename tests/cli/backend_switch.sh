#!/usr/bin/env bash
# The move between threads and one thread (docs/benchmarks.md, "A busy machine"):
# 1. `--backend-switch alternate` moves the solver to the other backend after every slice;
#    the run must be bitwise the same as one that stays on the threads
#    (tests/parallel/compare_runs.py: particles bitwise, sums to round-off), and must have
#    moved.
# 2. Beside as many busy processes as this machine has CPUs, a run with the default switch
#    finishes (a guard against a hang: the limit is generous, not a timing), saw the load
#    at its start and started on one thread (machine_load.hpp), and reports its moves.
# Usage: backend_switch.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
busy=()
trap 'for p in "${busy[@]}"; do kill "$p" 2>/dev/null; done; rm -rf "$dir"' EXIT
status=0
fail() {
  echo "FAIL: $*"
  status=1
}
# The default scene for 6 ms: 30 000 steps, 8 000 particles at the end; snapshots and a
# checkpoint to compare.
short=(--quiet --set time.duration=0.006 --set time.production_start=0.003
  --set output.snapshot_interval=0.002 --set output.checkpoint_interval=0.003
  --set 'numerics.bin_size="6 d"' --set output.blocks=2)
export OMP_NUM_THREADS=2 OMP_PROC_BIND=false
"$granshock" run "$scene" "${short[@]}" --backend-switch off --out "$dir/threads" ||
  fail "the run on the threads"
"$granshock" run "$scene" "${short[@]}" --backend-switch alternate --out "$dir/alternate" ||
  fail "the run that alternates"
/usr/bin/python3 "$here/../parallel/compare_runs.py" "$dir/threads" "$dir/alternate" 1 ||
  fail "moving between the backends changed the run"
moves=$(/usr/bin/python3 -c 'import json, sys
print(json.load(open(sys.argv[1])).get("backend_switch", {}).get("moves", 0))' "$dir/alternate/summary.json")
[ "$moves" -gt 10 ] || fail "the alternating run moved $moves times"
[ "$(/usr/bin/python3 -c 'import json, sys
print("backend_switch" in json.load(open(sys.argv[1])))' "$dir/threads/summary.json")" = True ] &&
  fail "--backend-switch off reported a backend switch"

# A busy process for each CPU beside a run on 2 threads.
for _ in $(seq "$(nproc)"); do
  yes >/dev/null &
  busy+=($!)
done
timeout 600 "$granshock" run "$scene" "${short[@]}" --out "$dir/busy" ||
  fail "the run beside the busy processes did not finish (exit $?)"
/usr/bin/python3 -c 'import json, sys
s = json.load(open(sys.argv[1]))
b = s["backend_switch"]
print("beside %s busy processes: %.3g particle-steps/s, started on %s, %d moves, %.2f of %.2f s on one thread"
      % (sys.argv[2], s["particle_steps_per_second"], b["started_on"], b["moves"],
         b["seconds_on_one_thread"], b["seconds_timed"]))
sys.exit(0 if s["completed"] else 1)' "$dir/busy/summary.json" "$(nproc)" ||
  fail "no completed summary with its backend"
grep -q '"started_on": "one thread"' "$dir/busy/summary.json" ||
  fail "the run beside the busy processes did not start on one thread"
grep -q 'starting on one thread' "$dir/busy/log.txt" || fail "log.txt has no note of the start"
# Without the busy processes the run starts on the threads, unless other work on this
# machine keeps its CPUs busy (another test, a build), which the run's note then names.
for p in "${busy[@]}"; do kill "$p" 2>/dev/null; done
wait "${busy[@]}" 2>/dev/null
busy=()
"$granshock" run "$scene" "${short[@]}" --set time.duration=0.001 --set time.production_start=0.0005 \
  --out "$dir/idle" || fail "the run without the busy processes"
grep -q '"started_on": "threads"' "$dir/idle/summary.json" ||
  grep -q 'starting on one thread: [1-9][0-9]* other task' "$dir/idle/log.txt" ||
  fail "the run without the busy processes started on one thread without naming the load"
[ "$status" -eq 0 ] && echo "PASS"
exit $status

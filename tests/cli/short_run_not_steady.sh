#!/usr/bin/env bash
# A run much shorter than its flow-through time (docs/fields.md, section 12): the default
# scene for 0.02 s, averaged from 0.01 s, while L/U = 0.2 s. Its numbers come with the
# flag: summary.json "steady": false and the warning, the same warning on stderr, and the
# result line says so.
# Usage: short_run_not_steady.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$granshock" run "$scene" --out "$dir/run" --set time.duration=0.02 \
  --set time.production_start=0.01 --set output.progress_interval=1000 \
  >"$dir/out" 2>"$dir/err" || { echo "the run failed: $(tail -3 "$dir/err")"; exit 1; }
status=0
fail() {
  echo "FAIL: $*"
  status=1
}
summary=$dir/run/summary.json
grep -q '"steady": false' "$summary" || fail "summary.json: $(grep '"steady"' "$summary")"
grep -q '"steady_warning": "not yet steady: the window starts at 0.01 s, before the gas that met the obstacle at t = 0 has left the domain (0.09 s; L/U = 0.2 s)' "$summary" ||
  fail "summary.json: $(grep steady_warning "$summary")"
grep -q '"start_after_washout": false' "$summary" || fail "summary.json: no start_after_washout false"
grep -q "^granshock: warning: .*: not yet steady: the window starts at 0.01 s" "$dir/err" ||
  fail "no warning on stderr: $(cat "$dir/err")"
grep -q "NOT YET STEADY" "$dir/out" || fail "the result line: $(grep 'granshock fields' "$dir/out")"
[ "$status" = 0 ] && echo "a 0.02 s run is flagged: $(grep -o '"steady_warning": "[^"]*' "$summary")"
exit $status

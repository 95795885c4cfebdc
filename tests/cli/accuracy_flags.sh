#!/usr/bin/env bash
# --accuracy and --accuracy-table read strictly (docs/accuracy.md): an empty budget ran with
# no budget, --accuracy-table alone was ignored, 0x5% was read as 5 %, and a table of
# another version was used. Each is one line and exit code 2 now, for run and study, and
# writes nothing. Also the thread-count note quotes OMP_NUM_THREADS as given: a count past
# int read as 1215752191 threads.
# Usage: accuracy_flags.sh GRANSHOCK SOURCE_DIR
set -u
granshock=$1 source=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene=$source/scenes/paper/d50_u2375.toml
table=$source/docs/results/tradeoff/paper_d50_u2375/trade.json
study=$source/studies/paper.toml
status=0
expect() { "$here/expect_user_error.sh" "$@" || { echo "FAIL: ${*:2}"; status=1; }; }

for command in "run $scene --out $tmp/never --dry-run" "study $study --out $tmp/never --dry-run"; do
  # shellcheck disable=SC2086
  set -- $command
  expect "--accuracy: '': give the error budget as a percentage" "$granshock" "$@" --accuracy ''
  expect "--accuracy: '0x5%': give the error budget as a percentage" "$granshock" "$@" --accuracy 0x5%
  expect "--accuracy: ' 5%': give the error budget" "$granshock" "$@" --accuracy ' 5%'
  expect "--accuracy: 'inf%': give the error budget" "$granshock" "$@" --accuracy inf%
  expect "--accuracy-table requires --accuracy" "$granshock" "$@" --accuracy-table "$table"
done
/usr/bin/python3 - "$table" "$tmp" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
t["table"] = "granshock trade table 99"
json.dump(t, open(sys.argv[2] + "/v99.json", "w"))
del t["table"]
json.dump(t, open(sys.argv[2] + "/none.json", "w"))
PY
expect "v99\.json: is of version '\"granshock trade table 99\"', not \"granshock trade table 2\"" \
  "$granshock" run "$scene" --out "$tmp/never" --dry-run --accuracy 5% --accuracy-table "$tmp/v99.json"
expect "none\.json: is of no version, not \"granshock trade table 2\"" \
  "$granshock" run "$scene" --out "$tmp/never" --dry-run --accuracy 5% --accuracy-table "$tmp/none.json"
# A budget in decimals is a budget.
"$granshock" run "$scene" --out "$tmp/never" --dry-run --accuracy 5.0% >/dev/null 2>"$tmp/err" ||
  { echo "FAIL: --accuracy 5.0% refused:"; cat "$tmp/err"; status=1; }
[ ! -e "$tmp/never" ] || { echo "FAIL: a --dry-run wrote $tmp/never"; status=1; }

OMP_NUM_THREADS=99999999999 "$granshock" info >/dev/null 2>"$tmp/err"
grep -q "OMP_NUM_THREADS asks for 99999999999 threads; capped at" "$tmp/err" ||
  { echo "FAIL: the thread note does not quote OMP_NUM_THREADS:"; cat "$tmp/err"; status=1; }
# 2^32 + 1 wraps to 1 thread in the runtime, silently before.
OMP_NUM_THREADS=4294967297 "$granshock" info >/dev/null 2>"$tmp/err"
grep -q "OMP_NUM_THREADS asks for 4294967297 threads; capped at" "$tmp/err" ||
  { echo "FAIL: OMP_NUM_THREADS=4294967297 gave no note:"; cat "$tmp/err"; status=1; }
[ $status -eq 0 ] && echo PASS
exit $status

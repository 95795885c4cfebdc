#!/usr/bin/env bash
# A disk that fills up during a run, made with a file-size limit (writes past it fail with
# EFBIG, as on a full disk), at several sizes (docs/output_format.md, "A full disk"). The run
# must stop with exit code 2 and one line on stderr that names the failed write and what
# survives it, and leave no temporary file. Where a checkpoint was written, it must be
# readable at the step the line names, and --resume (with room again) must finish the run
# bitwise the same as one that never stopped (tests/parallel/compare_runs.py); where none
# was, --resume must say to start again with --overwrite.
# Usage: full_disk.sh GRANSHOCK SCENE WORK reference   the uninterrupted run, into WORK
#        full_disk.sh GRANSHOCK SCENE WORK LIMIT_KIB   the run under `ulimit -f LIMIT_KIB`
set -u
granshock=$1 scene=$2 work=$3 mode=$4
here=$(cd "$(dirname "$0")" && pwd)
short=(--quiet --set time.duration=0.006 --set time.production_start=0.003
       --set output.snapshot_interval=0.0005 --set output.checkpoint_interval=0.002
       --set 'numerics.bin_size="6 d"' --set output.blocks=2)
if [ "$mode" = reference ]; then
  rm -rf "$work/reference" && mkdir -p "$work" &&
    exec "$granshock" run "$scene" "${short[@]}" --out "$work/reference"
fi
limit=$mode
dir=$work/limit$limit
rm -rf "$dir" && mkdir -p "$work"
(
  ulimit -f "$limit"  # KiB
  exec "$granshock" run "$scene" "${short[@]}" --out "$dir"
) >"$dir.out" 2>"$dir.err"
code=$?
grep -v -e '^Kokkos::OpenMP::initialize WARNING' -e '^  ' "$dir.err" >"$dir.own" || true
status=0
fail() { echo "FAIL: $*"; status=1; }
[ "$code" -eq 2 ] || fail "expected exit code 2, got $code"
[ "$(wc -l <"$dir.own")" -eq 1 ] || { fail "expected one line on stderr:"; cat "$dir.own"; }
cat "$dir.own"
if ls "$dir"/*.tmp >/dev/null 2>&1; then fail "a temporary file was left:"; ls "$dir"; fi
if grep -q "no checkpoint had been written yet" "$dir.own"; then
  grep -Eq "failed.*File too large.*: make room and start again with --overwrite" "$dir.own" ||
    fail "stderr does not name the failure and say to start again"
  "$granshock" run "$scene" "${short[@]}" --out "$dir" --resume >/dev/null 2>"$dir.resume"
  resumed=$?
  [ "$resumed" -eq 2 ] && grep -q "holds run.h5 but no checkpoint.h5: the run was stopped before its first checkpoint; start again with --overwrite" "$dir.resume" ||
    { fail "--resume without a checkpoint (exit $resumed) did not say to start again:"; cat "$dir.resume"; }
  [ "$status" -eq 0 ] && echo "PASS"
  exit $status
fi
grep -Eq "failed.*File too large.*checkpoint.h5 \(step [0-9]+\) is intact: make room and continue with --resume" "$dir.own" ||
  fail "stderr does not name the failure and the checkpoint"
step=$(sed -n 's/.*checkpoint.h5 (step \([0-9]*\)).*/\1/p' "$dir.own")
stored=$(h5dump -a /state/step "$dir/checkpoint.h5" 2>/dev/null | sed -n 's/ *(0): \([0-9]*\).*/\1/p')
[ -n "$step" ] && [ "$stored" = "$step" ] ||
  fail "checkpoint.h5 is not readable at step '$step' (read '$stored')"
# Room again: the run continues where the checkpoint left it, to the same end.
"$granshock" run "$scene" "${short[@]}" --out "$dir" --resume 2>"$dir.resume" ||
  { fail "the resume after the full disk failed:"; cat "$dir.resume"; }
/usr/bin/python3 "$here/../parallel/compare_runs.py" "$work/reference" "$dir" 1 ||
  fail "the resumed run differs from the uninterrupted one"
[ "$status" -eq 0 ] && echo "PASS"
exit $status

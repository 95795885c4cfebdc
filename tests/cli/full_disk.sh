#!/usr/bin/env bash
# A disk that fills up during a run, made with a file-size limit (writes past it fail with
# EFBIG, as on a full disk): the run must stop with exit code 2 and one line on stderr that
# names the failed write and the intact checkpoint, leave no temporary file, and the
# checkpoint it names must still be readable at that step.
# Usage: full_disk.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
(
  ulimit -f 1500  # KiB: room for the first checkpoint, not for the run
  exec "$granshock" run "$scene" --out "$dir/run" --quiet --set time.duration=0.02 \
    --set time.production_start=0.01 --set output.snapshot_interval=0.0005 \
    --set output.checkpoint_interval=0.002 --set 'numerics.bin_size="6 d"' --set output.blocks=2
) >"$dir/out" 2>"$dir/err"
code=$?
grep -v -e '^Kokkos::OpenMP::initialize WARNING' -e '^  ' "$dir/err" >"$dir/own" || true
status=0
[ "$code" -eq 2 ] || { echo "expected exit code 2, got $code"; status=1; }
[ "$(wc -l <"$dir/own")" -eq 1 ] || { echo "expected one line on stderr:"; cat "$dir/own"; status=1; }
grep -Eq "failed.*File too large.*checkpoint.h5 \(step [0-9]+\) is intact" "$dir/own" ||
  { echo "stderr does not name the failure and the checkpoint:"; cat "$dir/own"; status=1; }
if ls "$dir"/run/*.tmp >/dev/null 2>&1; then echo "a temporary file was left:"; ls "$dir/run"; status=1; fi
step=$(sed -n 's/.*checkpoint.h5 (step \([0-9]*\)).*/\1/p' "$dir/own")
stored=$(h5dump -a /state/step "$dir/run/checkpoint.h5" 2>/dev/null | sed -n 's/ *(0): \([0-9]*\).*/\1/p')
[ -n "$step" ] && [ "$stored" = "$step" ] ||
  { echo "checkpoint.h5 is not readable at step '$step' (read '$stored')"; status=1; }
exit $status

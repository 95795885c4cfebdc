#!/usr/bin/env bash
# SIGTERM and SIGINT outside the time loop (docs/output_format.md, "Signals"): the run ends
# with one line saying what was kept and what to do, and exit code 128 + signal, and the
# next command on the directory says the same.
# Usage: signals.sh GRANSHOCK SCENE MODE
#   at_start      a SIGTERM already pending when granshock starts (sent while MPI and
#                 Kokkos start): the setup stops, nothing is written
#   calibration   SIGTERM while sigma is calibrated (inflow.mach_at = "inlet_bins"):
#                 nothing is written, and --resume finds no directory
#   prefill       SIGTERM while a large domain is prefilled, after the directory was
#                 claimed: no checkpoint; --resume says to start again with --overwrite,
#                 and --overwrite accepts the directory
#   analysis      SIGINT during the final field analysis (a Python that draws until
#                 granshock is gone): the run's data is complete and `granshock fields DIR`
#                 redoes the analysis
set -u
granshock=$1 scene=$2 mode=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$work/run
status=0
fail() { echo "FAIL: $*"; status=1; }
own() { grep -v -e '^Kokkos::OpenMP::initialize WARNING' -e '^  ' "$1" || true; }
# expect_end CODE PATTERN: the exit code and the one line of stderr ($work/err)
expect_end() {
  own "$work/err" >"$work/own"
  cat "$work/own"
  [ "$code" -eq "$1" ] || fail "exit code $code, expected $1"
  [ "$(grep -c 'granshock: error\|interrupted' "$work/own")" -eq 1 ] && grep -q -- "$2" "$work/own" ||
    fail "stderr does not say: $2"
}
# wait_for PATH PID: until PATH exists (or the process ended)
wait_for() {
  for _ in $(seq 1 6000); do
    [ -e "$1" ] && return 0
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.01
  done
  return 1
}
short=(--set time.duration=0.002 --set time.production_start=0.001)

case $mode in
at_start)
  # Blocked and pending in the process that execs granshock: delivered the moment granshock
  # unblocks it, as a signal sent during its first tenth of a second would be.
  /usr/bin/python3 -c 'import os, signal, sys
signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGTERM})
os.kill(os.getpid(), signal.SIGTERM)
os.execv(sys.argv[1], sys.argv[1:])' "$granshock" run "$scene" --out "$out" "${short[@]}" \
    2>"$work/err"
  code=$?
  expect_end 143 "granshock: interrupted by SIGTERM while setting up the run, before anything was written to '$out'; run the same command again"
  [ ! -e "$out" ] || fail "the run directory was created"
  ;;
calibration)
  "$granshock" run "$scene" --out "$out" "${short[@]}" --set 'inflow.mach_at="inlet_bins"' \
    2>"$work/err" &
  pid=$!
  for _ in $(seq 1 3000); do grep -q "calibrating sigma" "$work/err" && break; sleep 0.01; done
  sleep 0.2
  kill -TERM $pid
  wait $pid
  code=$?
  expect_end 143 "interrupted by SIGTERM while setting up the run, before anything was written"
  [ ! -e "$out" ] || fail "the run directory was created"
  "$granshock" run "$scene" --out "$out" "${short[@]}" --resume 2>"$work/err"
  code=$?
  expect_end 2 "--resume: output directory '$out' does not exist"
  ;;
prefill)
  # 500 d x 500 d: about 30 000 particles to place, seconds of prefill.
  big=(--set 'domain.width="500 d"' --set 'domain.length="500 d"'
       --set 'obstacle.centre=["250 d", "250 d"]')
  "$granshock" run "$scene" --out "$out" "${short[@]}" "${big[@]}" 2>"$work/err" &
  pid=$!
  wait_for "$out/.granshock-run" $pid || fail "the run never claimed its directory"
  kill -TERM $pid
  wait $pid
  code=$?
  expect_end 143 "interrupted by SIGTERM before the first checkpoint (while prefilling the domain); '$out' holds no checkpoint to resume: start again with --overwrite"
  [ ! -e "$out/checkpoint.h5" ] || fail "a checkpoint was written"
  "$granshock" run "$scene" --out "$out" "${short[@]}" "${big[@]}" --resume 2>"$work/err"
  code=$?
  expect_end 2 "--resume: '$out' holds run.h5 but no checkpoint.h5: the run was stopped before its first checkpoint; start again with --overwrite"
  "$granshock" run "$scene" --out "$out" "${short[@]}" "${big[@]}" --overwrite --dry-run \
    >/dev/null 2>"$work/err" || { cat "$work/err"; fail "--overwrite refused the directory"; }
  ;;
analysis)
  # Imports anything at once (the check before the figures), then draws until granshock
  # is gone (at most 20 s: a granshock that ignored the signal waits for it). The figures
  # are asked for: they are the analysis' step that lasts until the signal.
  printf '#!/bin/sh\n[ "$1" = -c ] && exit 0\nfor i in $(seq 400); do kill -0 $PPID 2>/dev/null || exit 0; sleep 0.05; done\n' \
    >"$work/python"
  chmod +x "$work/python"
  GRANSHOCK_FIGURES=1 GRANSHOCK_PYTHON=$work/python "$granshock" run "$scene" --out "$out" "${short[@]}" --quiet \
    2>"$work/err" &
  pid=$!
  # summary.json is written just before the analysis starts.
  wait_for "$out/summary.json" $pid || fail "the run never wrote summary.json"
  sleep 0.3
  kill -INT $pid
  wait $pid
  code=$?
  expect_end 130 "granshock: interrupted during the field analysis; the run's data is complete (checkpoint.h5, run.h5, summary.json): \`granshock fields $out\` redoes the analysis"
  GRANSHOCK_PYTHON=/bin/true "$granshock" fields "$out" >/dev/null 2>"$work/err" ||
    { cat "$work/err"; fail "granshock fields did not redo the analysis"; }
  ;;
*)
  fail "unknown mode $mode"
  ;;
esac
[ "$status" -eq 0 ] && echo "PASS"
exit $status

#!/usr/bin/env bash
# The device check on a machine whose Python lacks h5py (the H200 of 27 November 2026
# evening: its stock Python 3.12 had none, and both runs FAILed at their digests, losing
# them): the runs still run and pass, their comparisons are DEFERRED (exit 3) with the
# files the digests need in deferred.tar.gz, and `gpu_check.sh --finish` on that archive
# digests them as the run's own files digest and gives the comparison's verdict.
# Usage: gpu_check_defers_digests.sh REPO BUILD_DIR
set -uo pipefail
repo=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# A Python whose `import h5py` fails, as on that machine.
mkdir -p "$work/block"
echo 'raise ImportError("no h5py here (this test)")' >"$work/block/h5py.py"
printf '#!/bin/sh\nPYTHONPATH=%s exec /usr/bin/python3 "$@"\n' "$work/block" >"$work/python"
chmod +x "$work/python"

GRANSHOCK_GPU_CHECK_BUILD=$build GRANSHOCK_GPU_CHECK_ONLY="default_scene compare_default_scene" \
  GRANSHOCK_PYTHON=$work/python GRANSHOCK_GPU_CHECK_OUT=$work/device \
  bash "$repo/apps/bench/gpu_check.sh" >"$work/device.txt" 2>&1
rc=$?
cat "$work/device.txt"
[ "$rc" = 3 ] || fail "exit $rc without h5py, expected 3 (every step ok or deferred)"
grep -q '^| default_scene | ok |' "$work/device.txt" || fail "the run did not pass without h5py"
grep -q '^| compare_default_scene | DEFERRED |' "$work/device.txt" || fail "no DEFERRED comparison"
grep -q 'paper_d50_u1000\|gas_' "$work/device.txt" && fail "steps outside GRANSHOCK_GPU_CHECK_ONLY ran"
[ -f "$work/device/deferred.tar.gz" ] || fail "no deferred.tar.gz"

mkdir -p "$work/host"
cp "$work/device/deferred.tar.gz" "$work/host/"
bash "$repo/apps/bench/gpu_check.sh" --finish "$work/host" >"$work/host.txt" 2>&1
rc=$?
cat "$work/host.txt"
[ "$rc" = 0 ] || [ "$rc" = 1 ] || fail "--finish exit $rc"
grep -q '^| digest_default_scene | ok |' "$work/host.txt" || fail "--finish did not digest"
grep -qE '^(ok|FAIL): ' "$work/host/compare_default_scene.log" || fail "--finish gave no verdict"
# The archive's digest is the run's own.
/usr/bin/python3 "$repo/apps/bench/gpu_check_compare.py" digest "$work/device/default_scene" \
  >"$work/direct.json" || fail "digest of the run itself"
cmp -s "$work/direct.json" "$work/host/default_scene.json" ||
  fail "the deferred digest differs from the run's own"
echo "gpu_check: digests deferred without h5py and finished on the host"

#!/usr/bin/env bash
# Runs cases of a study on a GPU machine within a wall-time limit and keeps the small
# results (docs/cuda.md, "Study cases on a GPU"): the machines lent for device checks run
# one command for minutes, so each call runs what fits and brings back what docs/results
# publish (summary.json, fields.xmf, log.txt, detachment_convergence.csv, the progress
# lines; fields.h5 with KEEP_FIELDS=1), never the checkpoint or run.h5.
# The cases run one after another: two at once on one H200 ran at 1.1e8 and 1.4-2e8
# particle-steps/s against 1.1e9 for one alone (docs/cuda.md). At the limit the running
# case is interrupted (SIGINT: it writes its checkpoint and stops) and the rest are not
# started; the study directory WORK stays on the machine, so a second call on the same
# warm machine resumes where the first stopped.
#
# Usage: apps/bench/gpu_study.sh STUDY.toml CASE...    (CASE: the index of --case)
# Environment: GRANSHOCK (default build-cuda/apps/granshock/granshock; with
#   build-cuda/runtime-libs/ from apps/bench/gpu_bundle.sh on LD_LIBRARY_PATH), OUT
#   (default ./gpu-study-out), WORK (default /tmp/granshock-gpu-study), LIMIT_S (default
#   480: wall seconds for all the cases), KEEP_FIELDS (default 0).
set -uo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
study=${1:?usage: gpu_study.sh STUDY.toml CASE...}
shift
[ $# -gt 0 ] || { echo "gpu_study.sh: name at least one case index" >&2; exit 2; }
granshock=${GRANSHOCK:-$repo/build-cuda/apps/granshock/granshock}
out=${OUT:-$PWD/gpu-study-out}
work=${WORK:-/tmp/granshock-gpu-study}
limit=${LIMIT_S:-480}
libs=$(dirname "$(dirname "$(dirname "$granshock")")")/runtime-libs
if [ -d "$libs" ]; then
  export LD_LIBRARY_PATH=$libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  ldd "$granshock" 2>&1 | grep -q "not found" &&
    export LD_LIBRARY_PATH=$libs/cxx-runtime:$LD_LIBRARY_PATH
fi
[ -x "$granshock" ] || { echo "gpu_study.sh: no $granshock" >&2; exit 2; }
mkdir -p "$out" "$work"
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | sed 's/^/GPU: /'
files=(summary.json fields.xmf log.txt detachment_convergence.csv)
[ "${KEEP_FIELDS:-0}" = 1 ] && files+=(fields.h5)
start=$SECONDS
for k in "$@"; do
  left=$((limit - (SECONDS - start)))
  if [ "$left" -le 20 ]; then
    echo "== case $k: not started ($((SECONDS - start)) s of $limit used)"
    continue
  fi
  # --no-figures: the machine may lack matplotlib; `granshock fields DIR` draws them later.
  timeout -s INT "$left" "$granshock" study "$study" --out "$work" --case "$k" --no-figures \
    >>"$out/progress_case_$k.txt" 2>&1
  echo "== case $k ($((SECONDS - start)) s): $(grep -E "done:|interrupted|stopped|error" \
    "$out/progress_case_$k.txt" | tail -n 1)"
done
for d in "$work"/*/; do
  [ -f "$d/log.txt" ] || continue
  mkdir -p "$out/$(basename "$d")"
  for f in "${files[@]}"; do [ -f "$d/$f" ] && cp "$d/$f" "$out/$(basename "$d")/"; done
done
echo "results: $out ($((SECONDS - start)) s)"

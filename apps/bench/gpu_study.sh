#!/usr/bin/env bash
# Runs cases of a study on a GPU machine within a wall-time limit and keeps the small
# results (docs/cuda.md, "Study cases on a GPU"): the machines lent for device checks run
# one command for minutes, so each call runs what fits and brings back what docs/results
# publish (summary.json, fields.xmf, log.txt, detachment_convergence.csv, the progress
# lines; fields.h5 with KEEP_FIELDS=1), never the checkpoint or run.h5.
# By default the cases run one after another: two at once on one H200 without MPS ran at
# 1.1e8 and 1.4-2e8 particle-steps/s against 1.1e9 for one alone (docs/cuda.md). At the
# limit the running case is interrupted (SIGINT: it writes its checkpoint and stops) and
# the rest are not started; the study directory WORK stays on the machine, so a second
# call on the same warm machine resumes where the first stopped.
# --concurrent K (K > 1) runs up to K cases side by side under CUDA's Multi-Process
# Service: a control daemon of this call's own (pipe and log directories in WORK.mps/, next
# to WORK: the study refuses a WORK that holds anything but its cases), started before
# the cases and quit after them, also on a failing case, on SIGINT/SIGTERM/SIGHUP (passed
# on to the running cases, which checkpoint first) and when the script fails partway (an
# EXIT trap). Without MPS (no nvidia-cuda-mps-control, or `-d` fails) the cases run one at
# a time, as without --concurrent: side by side without MPS they were 4 times slower.
#
# Usage: apps/bench/gpu_study.sh [--concurrent K] STUDY.toml CASE...
#   (CASE: the index of --case)
# Environment: GRANSHOCK (default build-cuda/apps/granshock/granshock; with
#   build-cuda/runtime-libs/ from apps/bench/gpu_bundle.sh on LD_LIBRARY_PATH), OUT
#   (default ./gpu-study-out), WORK (default /tmp/granshock-gpu-study), LIMIT_S (default
#   480: wall seconds for all the cases), KEEP_FIELDS (default 0).
set -uo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
usage="usage: gpu_study.sh [--concurrent K] STUDY.toml CASE..."
concurrent=1
case ${1:-} in
  --concurrent | --concurrent=*)
    if [ "$1" = --concurrent ]; then
      concurrent=${2:-}
      shift $(($# < 2 ? $# : 2))
    else
      concurrent=${1#--concurrent=}
      shift
    fi
    [[ $concurrent =~ ^[1-9][0-9]*$ ]] || {
      echo "gpu_study.sh: --concurrent takes a positive integer, not '$concurrent'" >&2
      echo "$usage" >&2
      exit 2
    } ;;
esac
study=${1:?$usage}
shift
[ $# -gt 0 ] || { echo "gpu_study.sh: name at least one case index" >&2; exit 2; }
for k in "$@"; do
  case $k in --concurrent*) echo "gpu_study.sh: --concurrent goes before STUDY.toml" >&2
    echo "$usage" >&2; exit 2 ;;
  esac
done
# More at once than there are cases is all of them at once (and a 20-digit K no overflow).
asked=$concurrent
if [ ${#concurrent} -gt 6 ] || [ "$concurrent" -gt $# ]; then concurrent=$#; fi
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

# One case after another, in the foreground (without --concurrent, and without MPS).
run_one_at_a_time() {
  local k left
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
}

copy_results() {
  local d f
  for d in "$work"/*/; do
    [ -f "$d/log.txt" ] || continue
    mkdir -p "$out/$(basename "$d")"
    for f in "${files[@]}"; do [ -f "$d/$f" ] && cp "$d/$f" "$out/$(basename "$d")/"; done
  done
}

# --- Several cases at once under MPS -------------------------------------------------
mps_dir=""      # the daemon's pipe/ and log/ (start_mps)
mps_up=0        # 1 from `-d` until `quit`
mps_reason=""   # why MPS is not used
declare -A running=()  # timeout's pid -> case index
poller=""       # the pid of the poll's sleep
started=0       # cases started side by side

mps_control() { timeout 30 nvidia-cuda-mps-control "$@"; }

# Starts this call's control daemon; on failure leaves mps_reason and nothing running.
start_mps() {
  if ! command -v nvidia-cuda-mps-control >/dev/null 2>&1; then
    mps_reason="nvidia-cuda-mps-control not found"
    return 1
  fi
  # Next to WORK, not in it (a study directory that holds anything but a study is
  # refused), the same on every call with this WORK; absolute, as the daemon and the
  # clients must find the same pipes.
  mps_dir=$(cd "$work" && pwd).mps || { mps_reason="no $work"; return 1; }
  mkdir -p "$mps_dir/pipe" "$mps_dir/log" || { mps_reason="cannot make $mps_dir"; return 1; }
  export CUDA_MPS_PIPE_DIRECTORY=$mps_dir/pipe CUDA_MPS_LOG_DIRECTORY=$mps_dir/log
  # A daemon that an earlier call left (one killed with SIGKILL): quit, then start afresh.
  local pid
  pid=$(cat "$mps_dir/pipe/nvidia-cuda-mps-control.pid" 2>/dev/null)
  if [[ $pid =~ ^[0-9]+$ ]] && kill -0 "$pid" 2>/dev/null; then
    echo "== MPS: an earlier call's daemon (pid $pid) runs in $mps_dir/pipe: quitting it"
    echo quit | mps_control >/dev/null 2>&1
    sleep 2
  fi
  rm -rf "${mps_dir:?}"/pipe/* "${mps_dir:?}"/log/*
  # Its output to a file: the daemon may keep the descriptors it was started with.
  if ! mps_control -d >"$mps_dir/start.txt" 2>&1 </dev/null; then
    mps_reason="nvidia-cuda-mps-control -d failed: $(head -c 200 "$mps_dir/start.txt" | head -n 1)"
    # Whatever it may have started (its pipes) is asked to quit.
    [ -n "$(ls -A "$mps_dir/pipe")" ] && echo quit | mps_control >/dev/null 2>&1
    unset CUDA_MPS_PIPE_DIRECTORY CUDA_MPS_LOG_DIRECTORY
    return 1
  fi
  mps_up=1
  # `-d` forks the daemon; the clients find it by the pipes it makes.
  local tries=50
  while [ "$tries" -gt 0 ]; do
    [ -n "$(ls -A "$mps_dir/pipe")" ] && return 0
    sleep 0.1
    tries=$((tries - 1))
  done
  mps_reason="nvidia-cuda-mps-control -d made no pipe in $mps_dir/pipe in 5 s"
  stop_mps
  unset CUDA_MPS_PIPE_DIRECTORY CUDA_MPS_LOG_DIRECTORY
  return 1
}

stop_mps() {
  [ "$mps_up" = 1 ] || return 0
  mps_up=0
  if echo quit | mps_control >>"$mps_dir/quit.txt" 2>&1; then
    echo "== MPS: daemon quit"
  else
    echo "gpu_study.sh: the MPS daemon did not take quit; stop it with:" \
      "echo quit | CUDA_MPS_PIPE_DIRECTORY=$mps_dir/pipe nvidia-cuda-mps-control" >&2
  fi
  if [ -n "$(ls -A "$mps_dir/log" 2>/dev/null)" ]; then
    mkdir -p "$out/mps" && cp -r "$mps_dir/log/." "$out/mps/"
  fi
}

# Reaps the cases that have ended and says how each ended.
reap_cases() {
  local pid k rc
  for pid in "${!running[@]}"; do
    kill -0 "$pid" 2>/dev/null && continue
    wait "$pid"
    rc=$?
    k=${running[$pid]}
    unset "running[$pid]"
    echo "== case $k ($((SECONDS - start)) s): $(grep -E "done:|interrupted|stopped|error" \
      "$out/progress_case_$k.txt" | tail -n 1)$([ "$rc" = 0 ] || echo " (exit $rc)")"
  done
}

# Passes signal $1 on to the running cases (timeout passes it to granshock, which writes
# its checkpoint) and waits for them: 120 s, then SIGKILL to their process groups.
stop_cases() {
  local pid deadline=$((SECONDS + 120))
  [ ${#running[@]} -gt 0 ] || return 0
  echo "== SIG$1 to the running cases: ${running[*]}"
  for pid in "${!running[@]}"; do kill -s "$1" "$pid" 2>/dev/null; done
  while reap_cases; [ ${#running[@]} -gt 0 ]; do
    if [ "$SECONDS" -ge "$deadline" ]; then
      echo "== cases ${running[*]} still running after 120 s: SIGKILL"
      # timeout leads its own process group (granshock is in it).
      for pid in "${!running[@]}"; do kill -KILL -- "-$pid" "$pid" 2>/dev/null; done
    fi
    sleep 0.2
  done
}

# Every way out of the script: the cases stopped, the daemon quit.
cleanup() {
  trap '' INT TERM HUP
  [ -n "$poller" ] && kill "$poller" 2>/dev/null
  stop_cases INT
  stop_mps
}

on_signal() {  # NAME NUMBER
  trap '' INT TERM HUP
  echo "== SIG$1 ($((SECONDS - start)) s)"
  # granshock checkpoints on SIGINT and SIGTERM; SIGHUP would end it without one.
  if [ "$1" = HUP ]; then stop_cases TERM; else stop_cases "$1"; fi
  stop_mps
  copy_results
  echo "results: $out ($((SECONDS - start)) s, stopped by SIG$1)"
  exit $((128 + $2))
}

run_side_by_side() {
  local queue=("$@") k left
  while [ ${#queue[@]} -gt 0 ] || [ ${#running[@]} -gt 0 ]; do
    while [ ${#queue[@]} -gt 0 ] && [ ${#running[@]} -lt "$concurrent" ]; do
      k=${queue[0]}
      queue=("${queue[@]:1}")
      left=$((limit - (SECONDS - start)))
      if [ "$left" -le 20 ]; then
        echo "== case $k: not started ($((SECONDS - start)) s of $limit used)"
        continue
      fi
      timeout -s INT "$left" "$granshock" study "$study" --out "$work" --case "$k" \
        --no-figures >>"$out/progress_case_$k.txt" 2>&1 </dev/null &
      running[$!]=$k
      started=$((started + 1))
      echo "== case $k: started ($((SECONDS - start)) s)"
    done
    [ ${#running[@]} -gt 0 ] || continue
    # A trapped signal ends `wait` at once (a foreground sleep would delay the trap).
    sleep 1 &
    poller=$!
    wait "$poller"
    poller=""
    reap_cases
  done
}

if [ "$concurrent" -gt 1 ]; then
  trap cleanup EXIT
  trap 'on_signal INT 2' INT
  trap 'on_signal TERM 15' TERM
  trap 'on_signal HUP 1' HUP
  if start_mps; then
    echo "== concurrency: MPS, $concurrent cases at a time (daemon: $mps_dir)"
    run_side_by_side "$@"
    stop_mps
    # A client that fails to reach the daemon runs without MPS, silently; the daemon
    # starts a server (and its server.log) for the first client that reaches it.
    if [ "$started" -gt 0 ] && [ -z "$(find "$mps_dir/log" -name server.log 2>/dev/null)" ]; then
      echo "== MPS: no server.log in $mps_dir/log: the cases may have run without MPS"
    fi
  else
    trap - EXIT INT TERM HUP
    echo "== concurrency: one at a time (no MPS: $mps_reason)"
    run_one_at_a_time "$@"
  fi
else
  [ "$asked" != 1 ] && echo "== concurrency: one at a time (one case)"
  run_one_at_a_time "$@"
fi
copy_results
echo "results: $out ($((SECONDS - start)) s)"

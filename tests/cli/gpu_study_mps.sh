#!/usr/bin/env bash
# apps/bench/gpu_study.sh --concurrent K without a GPU (docs/cuda.md, "Study cases on a
# GPU"): fakes of nvidia-cuda-mps-control, nvidia-smi and granshock first on PATH. The
# fake daemon is a marker file in its pipe directory (`-d` makes it, `quit` removes it);
# the fake granshock logs when each case starts and ends, sleeps, stops at SIGINT/SIGTERM
# as a real case does after its checkpoint, can fail (FAKE_FAIL_CASE), refuses a study
# directory that holds anything but its cases, as granshock does, and writes log.txt and
# summary.json for the copy step. Each scenario prints PASS/FAIL lines; exit 1 on a FAIL.
# Usage: gpu_study_mps.sh REPO
set -uo pipefail
repo=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
script=$repo/apps/bench/gpu_study.sh
tmp=$(mktemp -d)
bin=$tmp/bin
failures=0
script_pid=""

leftovers() {  # the fake granshock processes still alive (pids they recorded)
  local f pid
  for f in "$tmp"/pids/*; do
    [ -f "$f" ] || continue
    pid=$(cat "$f")
    kill -0 "$pid" 2>/dev/null && echo "$pid"
  done
}
# Ends what a failing scenario left: each fake with its process group (timeout's, which
# holds the fake and its sleep).
kill_leftovers() {
  local pid group
  for pid in $(leftovers); do
    group=$(ps -o pgid= -p "$pid" | tr -d ' ')
    [ -n "$group" ] && [ "$group" != "$(ps -o pgid= -p $$ | tr -d ' ')" ] &&
      kill -KILL -- "-$group" 2>/dev/null
    kill -KILL "$pid" 2>/dev/null
  done
}
finish() {
  [ -n "$script_pid" ] && kill -KILL "$script_pid" 2>/dev/null
  kill_leftovers
  rm -rf "$tmp"
}
trap finish EXIT

pass() { echo "PASS: $scenario: $*"; }
fail() { echo "FAIL: $scenario: $*"; failures=$((failures + 1)); }
check() {  # DESCRIPTION COMMAND...
  local what=$1
  shift
  if "$@"; then pass "$what"; else fail "$what"; fi
}

mkdir -p "$bin"
cat >"$bin/nvidia-cuda-mps-control" <<EOF
#!/usr/bin/env bash
log=$tmp/mps.log
if [ "\${1:-}" = -d ]; then
  echo "start \${CUDA_MPS_PIPE_DIRECTORY:-unset} \$(date +%s.%N)" >>"\$log"
  if [ -n "\${FAKE_MPS_FAIL:-}" ]; then echo "fake: cannot start the daemon: permission denied" >&2; exit 1; fi
  : >"\$CUDA_MPS_PIPE_DIRECTORY/daemon_running"
  echo "fake control daemon started" >>"\$CUDA_MPS_LOG_DIRECTORY/control.log"
  exit 0
fi
cmd=\$(cat)
echo "\$cmd \${CUDA_MPS_PIPE_DIRECTORY:-unset} \$(date +%s.%N)" >>"\$log"
if [ "\$cmd" = quit ] && [ -e "\${CUDA_MPS_PIPE_DIRECTORY:-/nonexistent}/daemon_running" ]; then
  rm "\$CUDA_MPS_PIPE_DIRECTORY/daemon_running"
  exit 0
fi
echo "Cannot find MPS control daemon process" >&2
exit 1
EOF
cat >"$bin/nvidia-smi" <<'EOF'
#!/usr/bin/env bash
echo "Fake GPU (test), 000.00"
EOF
cat >"$tmp/granshock" <<EOF
#!/usr/bin/env bash
# granshock study STUDY --out WORK --case K --no-figures, faked.
out="" k=""
while [ \$# -gt 0 ]; do
  case \$1 in --out) out=\$2; shift ;; --case) k=\$2; shift ;; esac
  shift
done
log=$tmp/granshock.log
mkdir -p "$tmp/pids"
echo \$\$ >"$tmp/pids/\$k"
echo "start \$k \$(date +%s.%N) \${CUDA_MPS_PIPE_DIRECTORY:-none}" >>"\$log"
sleeper=""
stop() {  # once: timeout passes a signal to granshock and again to its process group
  trap '' INT TERM
  echo "granshock study: case \$k interrupted by SIG\$1 (checkpoint written)"
  echo "interrupted \$k \$(date +%s.%N) \$1" >>"\$log"
  [ -n "\$sleeper" ] && kill "\$sleeper" 2>/dev/null
  exit "\$2"
}
trap 'stop INT 130' INT
trap 'stop TERM 143' TERM
if [ -n "\$(ls -A "\$out")" ] && [ ! -e "\$out/.granshock-study" ]; then
  echo "granshock: error: study directory '\$out' is not empty and holds no study"
  exit 2
fi
: >>"\$out/.granshock-study"
# A client that reaches the daemon gets a server, which writes server.log.
if [ -e "\${CUDA_MPS_PIPE_DIRECTORY:-/nonexistent}/daemon_running" ]; then
  echo "client \$k" >>"\$CUDA_MPS_LOG_DIRECTORY/server.log"
fi
sleep "\${FAKE_SLEEP:-1}" &
sleeper=\$!
wait "\$sleeper"
sleeper=""
if [ "\$k" = "\${FAKE_FAIL_CASE:-}" ]; then
  echo "granshock: error: case \$k failed (fake)"
  echo "end \$k \$(date +%s.%N) failed" >>"\$log"
  exit 1
fi
mkdir -p "\$out/case_\$k"
echo "fake log" >"\$out/case_\$k/log.txt"
echo "{}" >"\$out/case_\$k/summary.json"
echo "granshock study: case \$k done: fake"
echo "end \$k \$(date +%s.%N)" >>"\$log"
EOF
chmod +x "$bin"/* "$tmp/granshock"
echo '[study]' >"$tmp/study.toml"

# A fresh scenario: its own WORK, OUT and logs.
begin() {
  scenario=$1
  kill_leftovers
  rm -rf "$tmp/work" "$tmp/work.mps" "$tmp/out" "$tmp/pids" "$tmp/mps.log" "$tmp/granshock.log"
  : >"$tmp/mps.log"
  : >"$tmp/granshock.log"
}
run_study() {  # ARGS... (output in $tmp/output.txt, exit status in rc)
  PATH=$bin:$PATH GRANSHOCK=$tmp/granshock WORK=$tmp/work OUT=$tmp/out \
    bash "$script" "$@" >"$tmp/output.txt" 2>&1
  rc=$?
}
events() { awk -v e="$1" '$1 == e { print $2, $3 }' "$tmp/granshock.log"; }
# The most cases that ran at once, from the fake's start and end times.
most_at_once() {
  awk '$1 == "start" { print $3, 1 } $1 == "end" || $1 == "interrupted" { print $3, -1 }' \
    "$tmp/granshock.log" | sort -n -k1,1 -k2,2n |
    awk '{ n += $2; if (n > m) m = n } END { print m + 0 }'
}
overlapped() {  # every case started before any ended
  local last_start first_end
  last_start=$(events start | sort -k2,2n | tail -n 1 | cut -d' ' -f2)
  first_end=$(events end | sort -k2,2n | head -n 1 | cut -d' ' -f2)
  awk -v s="$last_start" -v e="$first_end" 'BEGIN { exit !(s != "" && e != "" && s < e) }'
}
one_after_another() {  # each case started after the one before it ended
  awk '$1 == "start" { if (running) bad = 1; running = 1 } $1 == "end" { running = 0 }
       END { exit bad }' "$tmp/granshock.log" && [ "$(events start | wc -l)" -gt 0 ]
}
no_daemon() { [ -z "$(find "$tmp" -name daemon_running)" ]; }
nothing_left() { [ -z "$(leftovers)" ]; }
# timeout or the fake, by command line ("granshock study": not this test's own commands).
no_fake_process() { ! pgrep -f -- "$tmp/granshock study" >/dev/null; }
said() { grep -qF -- "$1" "$tmp/output.txt"; }
mps_calls() { grep -c "^$1 " "$tmp/mps.log"; }
every_client_on() {  # every case's CUDA_MPS_PIPE_DIRECTORY was $1
  [ "$(events start | wc -l)" -gt 0 ] &&
    awk -v p="$1" '$1 == "start" && $4 != p { bad = 1 } END { exit bad }' "$tmp/granshock.log"
}
files() { local f; for f in "$@"; do [ -f "$f" ] || return 1; done; }
# Cases that stopped at signal $1: $2 of them, each at least once (timeout passes the
# signal to granshock and to its process group: a case may see it twice), none otherwise.
interrupted_by() {
  [ "$(events interrupted | cut -d' ' -f1 | sort -u | wc -l)" = "$2" ] &&
    awk -v s="$1" '$1 == "interrupted" && $4 != s { bad = 1 } END { exit bad }' \
      "$tmp/granshock.log" && return 0
  sed 's/^/    fake granshock: /' "$tmp/granshock.log"
  return 1
}
show() { sed 's/^/    | /' "$tmp/output.txt"; }

# (1) Three cases, three at a time: one daemon of this call's own, cases side by side.
begin "(1) --concurrent 3"
run_study --concurrent 3 "$tmp/study.toml" 0 1 2
show
pipe=$tmp/work.mps/pipe
check "exit 0" [ "$rc" = 0 ]
check "says MPS, 3 cases at a time" said "== concurrency: MPS, 3 cases at a time"
check "daemon started once" [ "$(mps_calls start)" = 1 ]
check "its pipe directory is WORK.mps/pipe" grep -qx "start $pipe [0-9.]*" "$tmp/mps.log"
check "every case a client of that daemon" every_client_on "$pipe"
check "the three cases overlap in time" overlapped
check "daemon quit once" [ "$(mps_calls quit)" = 1 ]
last_end=$(events end | sort -k2,2n | tail -n 1 | cut -d' ' -f2)
# shellcheck disable=SC2016 # awk's own $1 and $3
check "quit after the last case ended" awk -v t="$last_end" \
  '$1 == "quit" { q = $3 } END { exit !(q != "" && q > t) }' "$tmp/mps.log"
check "no daemon marker left" no_daemon
check "WORK holds only the study" [ -z "$(find "$tmp/work" -mindepth 1 -maxdepth 1 \
  ! -name 'case_*' ! -name .granshock-study)" ]
check "results copied" files "$tmp/out/case_0/summary.json" "$tmp/out/case_2/log.txt"
check "progress file per case" [ -s "$tmp/out/progress_case_1.txt" ]
check "a line per case done" [ "$(grep -c '^== case [0-2] (.*done: fake' "$tmp/output.txt")" = 3 ]
check "MPS logs brought back" [ -f "$tmp/out/mps/control.log" ]
check "no warning that MPS went unused" bash -c "! grep -q 'without MPS' '$tmp/output.txt'"

# (2) A case that fails (two at a time, three cases): the others run, the daemon quits.
begin "(2) a failing case"
FAKE_FAIL_CASE=1 FAKE_SLEEP=0.5 run_study --concurrent 2 "$tmp/study.toml" 0 1 2
show
check "the failure reported" said "error: case 1 failed (fake) (exit 1)"
check "never more than 2 at once" [ "$(most_at_once)" = 2 ]
check "the other cases ran" files "$tmp/out/case_0/log.txt" "$tmp/out/case_2/log.txt"
check "daemon quit" [ "$(mps_calls quit)" = 1 ]
check "no daemon marker left" no_daemon
check "nothing left running" nothing_left
check "no process of the fake left (pgrep)" no_fake_process

# Starts the script on K long cases, waits until all K run, sends it SIGNAL and waits up to
# 15 s for it to end; rc holds its exit status.
signal_while_running() {  # SIGNAL K
  local signal=$1 k=$2
  # shellcheck disable=SC2046 # the case indices, one word each
  PATH=$bin:$PATH GRANSHOCK=$tmp/granshock WORK=$tmp/work OUT=$tmp/out FAKE_SLEEP=30 \
    bash "$script" --concurrent "$k" "$tmp/study.toml" $(seq 0 $((k - 1))) >"$tmp/output.txt" 2>&1 &
  script_pid=$!
  for _ in $(seq 100); do
    [ "$(events start | wc -l)" = "$k" ] && break
    sleep 0.1
  done
  check "$k cases running" [ "$(events start | wc -l)" = "$k" ]
  kill -"$signal" "$script_pid"
  for _ in $(seq 150); do
    kill -0 "$script_pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$script_pid" 2>/dev/null; then
    fail "the script still runs 15 s after SIG$signal"
    kill -KILL "$script_pid"
  fi
  wait "$script_pid"
  rc=$?
  script_pid=""
}

# (3) SIGTERM while the cases run: passed on to them, daemon quit, nothing left.
begin "(3) SIGTERM"
signal_while_running TERM 3
show
check "exit 143" [ "$rc" = 143 ]
check "every case got SIGTERM (its checkpoint)" interrupted_by TERM 3
check "daemon quit" [ "$(mps_calls quit)" = 1 ]
check "no daemon marker left" no_daemon
check "no fake granshock left running" nothing_left
check "no process of the fake left (pgrep)" no_fake_process
kill_leftovers

# (3b) The script ended partway by something it does not trap (SIGUSR1 here; an error
# would end it the same way): its EXIT trap stops the cases (SIGINT) and the daemon.
begin "(3b) ended partway"
signal_while_running USR1 2
show
check "every case got SIGINT (its checkpoint)" interrupted_by INT 2
check "daemon quit" [ "$(mps_calls quit)" = 1 ]
check "no daemon marker left" no_daemon
check "no fake granshock left running" nothing_left
kill_leftovers

# (4) The daemon cannot start: one line, the cases one at a time, nothing running.
begin "(4) -d fails"
FAKE_MPS_FAIL=1 FAKE_SLEEP=0.3 run_study --concurrent 3 "$tmp/study.toml" 0 1 2
show
check "exit 0" [ "$rc" = 0 ]
check "says one at a time, and why" said \
  "== concurrency: one at a time (no MPS: nvidia-cuda-mps-control -d failed: fake: cannot start the daemon: permission denied)"
check "-d tried once, no quit" [ "$(mps_calls start) $(mps_calls quit)" = "1 0" ]
check "cases one after another" one_after_another
check "all three ran" [ "$(events end | wc -l)" = 3 ]
check "the cases saw no MPS pipe directory" every_client_on none
check "no daemon marker left" no_daemon
check "nothing left running" nothing_left

# (4b) No nvidia-cuda-mps-control at all (where this machine has none of its own).
begin "(4b) no nvidia-cuda-mps-control"
if PATH=/usr/bin:/bin command -v nvidia-cuda-mps-control >/dev/null; then
  echo "skipped: $scenario: this machine has nvidia-cuda-mps-control"
else
  mkdir -p "$tmp/bin-nomps"
  cp "$bin/nvidia-smi" "$tmp/bin-nomps/"
  PATH=$tmp/bin-nomps:/usr/bin:/bin FAKE_SLEEP=0.3 GRANSHOCK=$tmp/granshock WORK=$tmp/work \
    OUT=$tmp/out bash "$script" --concurrent 2 "$tmp/study.toml" 0 1 >"$tmp/output.txt" 2>&1
  rc=$?
  show
  check "exit 0" [ "$rc" = 0 ]
  check "says one at a time, and why" said \
    "== concurrency: one at a time (no MPS: nvidia-cuda-mps-control not found)"
  check "cases one after another" one_after_another
fi

# (5) --concurrent 1: today's script, MPS never called, the same output as without it.
begin "(5) --concurrent 1"
FAKE_SLEEP=0.3 run_study --concurrent 1 "$tmp/study.toml" 0 1
show
check "exit 0" [ "$rc" = 0 ]
check "MPS never called" [ ! -s "$tmp/mps.log" ]
check "no concurrency line" bash -c "! grep -q concurrency '$tmp/output.txt'"
check "cases one after another" one_after_another
check "results copied" [ -f "$tmp/out/case_1/summary.json" ]
sed -E 's/[0-9]+ s/N s/g' "$tmp/output.txt" >"$tmp/with_option.txt"
begin "(5) without --concurrent"
FAKE_SLEEP=0.3 run_study "$tmp/study.toml" 0 1
check "MPS never called" [ ! -s "$tmp/mps.log" ]
check "the same output as --concurrent 1" cmp -s "$tmp/with_option.txt" \
  <(sed -E 's/[0-9]+ s/N s/g' "$tmp/output.txt")

# (6) K not a positive integer, missing, or after the study: usage, exit 2, nothing run.
for bad in "0" "abc" "-1" "1.5" "" "after"; do
  begin "(6) --concurrent '$bad'"
  case $bad in
    after) run_study "$tmp/study.toml" 0 --concurrent 2 ;;
    "") run_study --concurrent ;;
    *) run_study --concurrent "$bad" "$tmp/study.toml" 0 1 ;;
  esac
  show
  check "exit 2" [ "$rc" = 2 ]
  check "a usage line" said "usage: gpu_study.sh [--concurrent K] STUDY.toml CASE..."
  check "no case started, MPS not called" [ -z "$(cat "$tmp/granshock.log" "$tmp/mps.log")" ]
done

if [ "$failures" -gt 0 ]; then
  echo "gpu_study_mps: $failures FAIL"
  exit 1
fi
echo "gpu_study_mps: all scenarios PASS"

#!/bin/bash
# `mpirun -np N granshock run` against one process (docs/parallel.md), on the default
# scene shortened to 4 ms (3,767 particles at the end, 20,000 steps, 41 list rebuilds, 5
# snapshots): enough to cross many rebuilds, migrations and (balanced) moves of the slab
# cuts, which compare_runs.py counts and requires.
# Usage: mpi_run.sh MPIEXEC GRANSHOCK SCENE WORK MODE [RANKS]
#   reference   the one-process runs, into WORK/one and WORK/one_big (a 60 d obstacle):
#               the fixture of the others
#   ranks N [T] [AXIS] [OUTPUT]  the run on N processes of T threads (default 1), slabs
#               along AXIS (--slabs, default y), snapshots OUTPUT (--snapshot-output,
#               default auto: gathered at this size): bitwise the same (compare_runs.py)
#   balanced N BY [AXIS]  the large obstacle with --balance BY (particles, work): bitwise,
#               and (particles) the cuts moved
#   resume [A B [OUTPUT]]  stopped on 2 processes half way (slabs along A, default y),
#               resumed on 3 (along B, default A), snapshots OUTPUT on both: the same as one
#               process
#   full_disk [OUTPUT]  the disk fills during a snapshot on 2 processes, written OUTPUT
#               (--snapshot-output, default collective): said once, no process left
#               waiting, and the run resumes to its end
#   errors      bad input (a scene, a directory, a box too narrow for the slabs) said once,
#               by one rank, exit code 2, no rank left waiting; other
#               commands than `run` refused under mpirun
#   progress    2 processes print progress lines at output.progress_interval, not at
#               every slice
set -u
mpiexec=$1 granshock=$2 scene=$3 work=$4 mode=$5
here=$(cd "$(dirname "$0")" && pwd)
short=(--quiet --set time.duration=0.004 --set time.production_start=0.002
  --set output.snapshot_interval=0.001)
mpi() { "$mpiexec" --oversubscribe -np "$@"; }
# compare DIR RANKS [ONE_PROCESS_DIR]
compare() { /usr/bin/python3 "$here/../parallel/compare_runs.py" "${3:-$work/one}" "$1" "$2"; }
# An obstacle of 60 d: the middle slabs hold fewer particles than the others.
big=(--set 'obstacle.diameter="60 d"')
fail() { echo "FAIL: $*"; exit 1; }

case $mode in
reference)
  rm -rf "$work" && mkdir -p "$work"
  "$granshock" run "$scene" "${short[@]}" --out "$work/one" || fail "the one-process run"
  "$granshock" run "$scene" "${short[@]}" "${big[@]}" --out "$work/one_big" ||
    fail "the one-process run with the large obstacle"
  ;;
ranks)
  # Hybrid: THREADS OpenMP threads in each process (default 1).
  ranks=$6 threads=${7:-1} axis=${8:-y} output=${9:-auto}
  out=$work/ranks${ranks}x${threads}_${axis}_$output
  rm -rf "$out"
  OMP_NUM_THREADS=$threads mpi "$ranks" "$granshock" run "$scene" "${short[@]}" --out "$out" \
    --slabs "$axis" --snapshot-output "$output" ||
    fail "the run on $ranks processes x $threads threads along $axis"
  compare "$out" "$ranks" || fail "$ranks processes x $threads threads along $axis differ from one"
  # The summary says the slabs and how the snapshots were written (auto: all gathered here).
  /usr/bin/python3 -c 'import json, sys
p = json.load(open(sys.argv[1]))["processes"]
collective = p["snapshots_written_collectively"]
print("snapshots:", p["snapshot_output"], collective, "of them written collectively")
sys.exit(0 if p["slabs_along"] == sys.argv[2] and p["snapshot_output"] == sys.argv[3] and
         (collective > 0) == (sys.argv[3] == "collective") else 1)' \
    "$out/summary.json" "$axis" "$output" ||
    fail "summary.json does not say slabs along $axis, snapshots $output"
  ;;
balanced)
  # Slab boundaries moved by particle count or measured work: the same bits, and (by
  # particle count, which does not depend on timings) the cuts did move.
  ranks=$6 by=$7 axis=${8:-y}
  out=$work/balanced_$by${ranks}_$axis
  rm -rf "$out"
  mpi "$ranks" "$granshock" run "$scene" "${short[@]}" "${big[@]}" --out "$out" \
    --balance "$by" --slabs "$axis" || fail "the run balanced by $by on $ranks processes"
  compare "$out" "$ranks" "$work/one_big" || fail "slabs balanced by $by differ from one process"
  /usr/bin/python3 -c 'import json, sys
p = json.load(open(sys.argv[1]))["processes"]
print("rebalances:", p["rebalances"], "balance:", p["balance"])
sys.exit(0 if p["balance"] == sys.argv[2] and (p["rebalances"] > 0 or sys.argv[2] == "work") else 1)' \
    "$out/summary.json" "$by" || fail "the slab boundaries never moved"
  ;;
resume)
  # A checkpoint holds the one-process state, whatever slabs wrote it.
  first=${6:-y} second=${7:-${6:-y}} output=${8:-auto}
  out=$work/resumed_${first}_${second}_$output
  rm -rf "$out"
  mpi 2 "$granshock" run "$scene" "${short[@]}" --out "$out" --stop-after-steps 10000 \
    --slabs "$first" --snapshot-output "$output" 2>"$work/stop.err" ||
    { cat "$work/stop.err"; fail "the first half on 2 processes"; }
  grep -q "stopped after 10000 steps" "$work/stop.err" || fail "no stop message"
  mpi 3 "$granshock" run "$scene" "${short[@]}" --out "$out" --resume --slabs "$second" \
    --snapshot-output "$output" || fail "the resume on 3 processes"
  compare "$out" 3 || fail "2 (along $first) then 3 processes (along $second) differ from one"
  ;;
errors)
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
  # Every rank meets it alike: said once.
  timeout 120 "$mpiexec" --oversubscribe -np 3 "$granshock" run "$dir/missing.toml" \
    --out "$dir/run" >"$dir/out" 2>"$dir/err"
  status=$?
  cat "$dir/err"
  [ "$status" -eq 2 ] || fail "a missing scene file: exit status $status, not 2"
  [ "$(grep -c "error" "$dir/err")" -eq 1 ] || fail "a missing scene file was not said once"
  [ ! -e "$dir/run" ] || fail "a run directory was created"
  # An existing run directory without --overwrite.
  mkdir "$dir/taken" && touch "$dir/taken/summary.json"
  timeout 120 "$mpiexec" --oversubscribe -np 3 "$granshock" run "$scene" "${short[@]}" \
    --out "$dir/taken" >"$dir/out" 2>"$dir/err"
  status=$?
  cat "$dir/err"
  [ "$status" -eq 2 ] || fail "an existing directory: exit status $status, not 2"
  [ "$(grep -c "error" "$dir/err")" -eq 1 ] || fail "an existing directory was not said once"
  # A run directory locked by another run: rank 0 alone probes the lock, fails alone
  # before the first collective step, and the others leave with it (failure_agreement.hpp).
  cp -r "$work/one" "$dir/locked"
  exec 9<"$dir/locked/.granshock-run"  # this shell holds the lock, as a running run would
  flock -x 9
  timeout 120 "$mpiexec" --oversubscribe -np 3 "$granshock" run "$scene" "${short[@]}" \
    --out "$dir/locked" --resume >"$dir/out" 2>"$dir/err"
  status=$?
  exec 9<&-
  cat "$dir/err"
  [ "$status" -eq 2 ] || fail "a locked directory: exit status $status, not 2"
  [ "$(grep -c "in use by another granshock run" "$dir/err")" -eq 1 ] ||
    fail "a locked directory was not said once"
  # Slabs along x in a box too narrow across x for 3 processes (4 cell columns, at least 2
  # per slab through the periodic faces): said once, naming the axis, nothing created.
  # (output.sample_every: enough field samples in 4 ms for the sampling check, which would
  # refuse the 1 d bins first.)
  timeout 120 "$mpiexec" --oversubscribe -np 3 "$granshock" run "$scene" "${short[@]}" \
    --out "$dir/narrow" --slabs x --set 'domain.width="6 d"' --set 'obstacle.diameter="3 d"' \
    --set 'obstacle.centre=["3 d", "120 d"]' --set 'numerics.bin_size="1 d"' \
    --set output.sample_every=10 >"$dir/out" 2>"$dir/err"
  status=$?
  cat "$dir/err"
  [ "$status" -eq 2 ] || fail "a box too narrow for slabs along x: exit status $status, not 2"
  [ "$(grep -c "with slabs along x need 6 cell columns" "$dir/err")" -eq 1 ] ||
    fail "a box too narrow for slabs along x was not said once, naming the axis"
  [ ! -e "$dir/narrow" ] || fail "a run directory was created for a box too narrow"
  # Commands other than run would do their whole job N times: refused, said once.
  timeout 120 "$mpiexec" --oversubscribe -np 2 "$granshock" fields "$dir/taken" \
    >"$dir/out" 2>"$dir/err"
  status=$?
  cat "$dir/err"
  [ "$status" -eq 2 ] || fail "fields under mpirun: exit status $status, not 2"
  [ "$(grep -c "started as 2 MPI processes" "$dir/err")" -eq 1 ] ||
    fail "fields under mpirun: the reason was not said once"
  # Without a launcher nothing changes; info reports the processes under one.
  "$granshock" info | grep -q '"launched": false' || fail "info without mpirun"
  mpi 2 "$granshock" info >"$dir/info" 2>&1
  [ "$(grep -c '"processes": 2' "$dir/info")" -eq 1 ] || { cat "$dir/info"; fail "info under mpirun"; }
  ;;
full_disk)
  # The disk fills during a collective snapshot write (a file-size limit on granshock's
  # processes, not on mpirun's): said once with the intact checkpoint, exit code 2, no
  # process left waiting in the collective write; then the run resumes to its end.
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
  tight=(--set output.snapshot_interval=0.0002 --set output.checkpoint_interval=0.001
         --set 'numerics.bin_size="6 d"' --set output.blocks=2 --snapshot-output "${6:-collective}")
  # The limit (1600 KiB) is met in a snapshot of this run (run.h5 of format 2, with radius
  # and frame views, reserves about 1 MB before a snapshot), before the checkpoint of step
  # 5000: the one of step 0 is intact. Room is reserved before every change, so the resume
  # always works.
  # Shared memory between the processes would meet the limit too (MPI warns and falls
  # back): TCP over the loopback between them keeps the test about granshock's write.
  timeout 120 "$mpiexec" --oversubscribe --mca btl self,tcp --mca btl_tcp_if_include lo -np 2 \
    bash -c 'ulimit -f 1600; exec "$@"' limited \
    "$granshock" run "$scene" "${short[@]}" "${tight[@]}" --out "$dir/run" >"$dir/out" 2>"$dir/err"
  status=$?
  grep "granshock" "$dir/err"
  [ "$status" -eq 2 ] || fail "a full disk under a collective write: exit status $status, not 2"
  [ "$(grep -Ec "granshock: error: writing .*run.h5.* failed.*checkpoint.h5 \(step [0-9]+\) is intact" \
      "$dir/err")" -eq 1 ] || fail "the full disk was not said once with the intact checkpoint"
  timeout 300 "$mpiexec" --oversubscribe -np 2 "$granshock" run "$scene" "${short[@]}" \
    "${tight[@]}" --out "$dir/run" --resume || fail "the resume after the full disk"
  /usr/bin/python3 -c 'import json, sys
sys.exit(0 if json.load(open(sys.argv[1]))["completed"] else 1)' "$dir/run/summary.json" ||
    fail "the resumed run did not complete"
  ;;
progress)
  # The slices end every 50 steps in the production window (output.sample_every): rank 0's
  # clock alone decides when a line is due, so about one a second, however many slices.
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
  start=$(date +%s)
  timeout 120 "$mpiexec" --oversubscribe -np 2 "$granshock" run "$scene" --no-figures \
    --set time.duration=0.01 --set time.production_start=0.002 \
    --set output.progress_interval=1 --out "$dir/run" >"$dir/out" 2>"$dir/err" ||
    { cat "$dir/err"; fail "the run on 2 processes"; }
  seconds=$(($(date +%s) - start))
  # The rows of the thermo table (cases/bow_shock/thermo_table.hpp): step, time, particles.
  lines=$(grep -cE '^ *[0-9]+ +[0-9.e+-]+ +[0-9]+ +[0-9]+ ' "$dir/err")
  allowed=$((seconds + 3))
  echo "$lines progress lines in $seconds s (at most $allowed)"
  [ "$lines" -ge 1 ] || fail "no progress line"
  [ "$lines" -le "$allowed" ] || fail "$lines progress lines in $seconds s at 1 s intervals"
  ;;
*)
  fail "unknown mode $mode"
  ;;
esac
echo "PASS"

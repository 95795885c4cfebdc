#!/usr/bin/env bash
# shellcheck disable=SC2317 # the functions run through `step` (bash -c), not inline
# The device check (docs/cuda.md, "The device check"): one command for a machine with an
# NVIDIA GPU and nvcc. It builds the CUDA variant with every core, then runs
# `granshock info`, the test suite, the gas benchmark at 32k and 2M particles (phi 0.1
# and 0.5), the default scene and a paper case for 0.05 s of simulated time, compares the
# two runs with the host's (apps/bench/gpu_check_reference.json: counts, energies, field
# sums, e_eff; apps/bench/gpu_check_compare.py) and prints one table. Every step has a
# time box (timeout); the boxes add up to 480 s, under 8 minutes of device time.
#
# Usage: apps/bench/gpu_check.sh [--record | --finish DIR]
#   GRANSHOCK_GPU_CHECK_DRY=1   the same steps on the host, on the device-path build
#                               (build-device/, -DGRANSHOCK_DEVICE_PATHS=ON): no GPU needed
#   --record                    the same steps on the host build (build/, host paths); writes
#                               the reference that the other two compare with
#   GRANSHOCK_GPU_CHECK_BOXES=F multiplies every time box by F (default 1; a 2-core host
#                               needs about 10 for the runs)
#   GRANSHOCK_GPU_CHECK_TESTS="ctest arguments"   a part of the suite instead of all of it
#   GRANSHOCK_GPU_CHECK_OUT=DIR logs, runs and the table (default gpu-check/ in the repo)
#   GRANSHOCK_GPU_CHECK_CMAKE="args"  more CMake configure arguments for the build
#   GRANSHOCK_GPU_CHECK_PREBUILT=1  no build: use build-cuda/ as apps/bench/gpu_bundle.sh
#                               unpacked it (a GPU machine without the Debian packages);
#                               its runtime-libs/ go on LD_LIBRARY_PATH
#   GRANSHOCK_GPU_CHECK_PROGRAMS="test_unit ..."  run these test programs directly (no
#                               ctest), with GRANSHOCK_GPU_CHECK_FILTER as --gtest_filter
#   GRANSHOCK_PYTHON=PATH       the Python with h5py and numpy (default /usr/bin/python3);
#                               without them (a GPU machine's stock Python) the runs still
#                               run, their digests and comparisons are DEFERRED and the
#                               files they need packed in DIR/deferred.tar.gz
#   --finish DIR                on a machine whose Python has h5py (the host): digest the
#                               deferred runs of DIR (a copy of GRANSHOCK_GPU_CHECK_OUT, or
#                               a folder holding its deferred.tar.gz) and compare them
#   GRANSHOCK_GPU_CHECK_ONLY="step ..."  run only the steps named (e.g. "default_scene
#                               compare_default_scene"); the others are left out of the table
#   GRANSHOCK_GPU_CHECK_BUILD=DIR  the build to check instead of the mode's own
# Exit status: 0 when every step is ok, 3 when every step is ok or DEFERRED, 1 otherwise.
set -uo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$repo" || exit 1
here=$repo/apps/bench
reference=$here/gpu_check_reference.json
out=${GRANSHOCK_GPU_CHECK_OUT:-$repo/gpu-check}
factor=${GRANSHOCK_GPU_CHECK_BOXES:-1}
jobs=$(nproc)
python=${GRANSHOCK_PYTHON:-/usr/bin/python3}
prebuilt=${GRANSHOCK_GPU_CHECK_PREBUILT:-0}
mode=gpu
[ "${GRANSHOCK_GPU_CHECK_DRY:-0}" = 1 ] && mode=dry
case "$#:${1:-}" in
  0:) ;;
  1:--record) mode=record ;;
  2:--finish) mode=finish out=$(cd "$2" 2>/dev/null && pwd) ||
    { echo "gpu_check.sh: --finish: no folder $2" >&2; exit 2; } ;;
  *) echo "gpu_check.sh: unexpected arguments '$*' (it takes --record, --finish DIR or" \
    "nothing)" >&2; exit 2 ;;
esac
case $mode in
  gpu) build=$repo/build-cuda expect="Cuda device" ;;
  dry) build=$repo/build-device expect="OpenMP device" ;;
  record | finish) build=$repo/build expect="OpenMP host" ;;
esac
build=${GRANSHOCK_GPU_CHECK_BUILD:-$build}
scene_runs=(default_scene paper_d50_u1000)  # the runs compared with the host's (step 5)
if [ "$mode" = finish ]; then
  # Only the digests and comparisons of the runs that are there.
  [ -f "$out/deferred.tar.gz" ] && tar -xzf "$out/deferred.tar.gz" -C "$out"
  GRANSHOCK_GPU_CHECK_ONLY=
  for name in "${scene_runs[@]}"; do
    [ -f "$out/$name/summary.json" ] &&
      GRANSHOCK_GPU_CHECK_ONLY+=" digest_$name compare_$name"
  done
  [ -n "$GRANSHOCK_GPU_CHECK_ONLY" ] ||
    { echo "gpu_check.sh: --finish: no deferred runs in $out" >&2; exit 2; }
else
  rm -rf "$out" && mkdir -p "$out"
fi
# The digests read HDF5: a Python without h5py defers them (the record needs them now).
digests=now
if ! "$python" -c 'import h5py, numpy' >/dev/null 2>&1; then
  [ "$mode" = gpu ] || [ "$mode" = dry ] || {
    echo "gpu_check.sh: $python has no h5py and numpy (GRANSHOCK_PYTHON names one that has)" >&2
    exit 2
  }
  digests=deferred
fi
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-2} OMP_PROC_BIND=false
export GRANSHOCK_FIGURES=0 GRANSHOCK_PYTHON="$python"  # no figures: nothing here checks them
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # the MPI tests, as root

rows=()
failed=0
deferred=0
total_box=0
start_all=$(date +%s)

# step NAME BOX_SECONDS COMMAND...: runs COMMAND, a program or one of the functions below
# (exported), within the box, its output in $out/NAME.log; then `row RESULT` adds the
# step's row to the table.
step() {
  local name=$1 box=$2
  shift 2
  local limit start rc
  step_name=$name
  if [ -n "${GRANSHOCK_GPU_CHECK_ONLY:-}" ] && [[ " $GRANSHOCK_GPU_CHECK_ONLY " != *" $name "* ]]; then
    step_status=skipped
    return 0
  fi
  limit=$(awk -v b="$box" -v f="$factor" 'BEGIN {printf "%d", b * f}')
  total_box=$((total_box + box))
  start=$(date +%s)
  timeout --kill-after=10 "$limit" bash -c '"$@"' step "$@" >"$out/$name.log" 2>&1
  rc=$?
  step_seconds=$(($(date +%s) - start))
  case $rc in
    0) step_status=ok ;;
    124 | 137) step_status=TIMEOUT ;;
    *) step_status=FAIL ;;
  esac
  step_box=$limit
}
row() {  # RESULT: the last step's row
  case $step_status in
    skipped) return 0 ;;
    ok) ;;
    DEFERRED) deferred=1 ;;
    *) failed=1 ;;
  esac
  rows+=("| $step_name | $step_status | $step_seconds | $step_box | $1 |")
}
log_tail() { tail -n 1 "$out/$1.log" 2>/dev/null | cut -c1-120; }

# 1. Build, with every core.
# shellcheck disable=SC2086 # GRANSHOCK_GPU_CHECK_CMAKE: arguments, split on purpose
build_variant() {
  case $mode in
    gpu) bash cmake/build_cuda.sh -DGRANSHOCK_BUILD_TESTS=ON ${GRANSHOCK_GPU_CHECK_CMAKE:-} ;;
    dry | record)
      local flags=()
      [ "$mode" = dry ] && flags=(-DGRANSHOCK_DEVICE_PATHS=ON)
      bash cmake/install_deps.sh &&
        cmake -S . -B "$build" -G Ninja "${flags[@]}" ${GRANSHOCK_GPU_CHECK_CMAKE:-} &&
        cmake --build "$build" --parallel "$jobs" ;;
  esac
}
# A prebuilt build (apps/bench/gpu_bundle.sh): its own libraries first; the C++ runtime it
# was built with only where the machine's own is older (a `not found` symbol version).
prebuilt_check() {
  local missing
  missing=$(ldd "$build"/apps/granshock/granshock "$build"/apps/bench/granshock_bench_gas \
    2>&1 | grep -E "not found" | sort -u)
  [ -z "$missing" ] && { echo "prebuilt ${build#"$repo"/}: every library found"; return 0; }
  echo "prebuilt ${build#"$repo"/}: missing: $missing" >&2
  return 1
}
if [ "$prebuilt" = 1 ]; then
  export LD_LIBRARY_PATH=$build/runtime-libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  if ! prebuilt_check >/dev/null 2>&1; then
    export LD_LIBRARY_PATH=$build/runtime-libs/cxx-runtime:$LD_LIBRARY_PATH
  fi
fi
export -f build_variant prebuilt_check
export mode repo build jobs out here reference python GRANSHOCK_GPU_CHECK_CMAKE
if [ "$prebuilt" = 1 ]; then
  step build 10 prebuilt_check
  row "$(log_tail build)"
else
  step build 210 build_variant
  row "$mode build in ${build#"$repo"/}, $jobs cores"
fi
granshock=$build/apps/granshock/granshock
bench=$build/apps/bench/granshock_bench_gas
export granshock

# 2. granshock info: the backend and the kernels' paths this mode must have.
step info 10 "$granshock" info
# The JSON starts at its first brace: Kokkos may warn on stderr before it (a GPU newer
# than the code's architecture, docs/cuda.md).
got=$($python -c 'import json, sys; t = open(sys.argv[1]).read(); j = json.loads(t[t.index("{"):]);
print(j["default_execution_space"], j.get("kernel_paths", "?"))' "$out/info.log" 2>/dev/null)
if [ "$step_status" = ok ] && [ "$got" != "$expect" ]; then step_status=FAIL; fi
row "${got:-no JSON} (expected: $expect)"

# 3. The test suite (or the part GRANSHOCK_GPU_CHECK_TESTS names), half the cores' worth
# of test programs at once (each runs 2 OpenMP threads).
# With GRANSHOCK_GPU_CHECK_PROGRAMS, the named test programs directly, one after the other
# (ctest's files name this machine's paths and its CMake; a prebuilt build has neither).
test_programs() {
  local program failed_programs=0
  for program in $GRANSHOCK_GPU_CHECK_PROGRAMS; do
    (cd "$build/tests" && "./$program" --gtest_brief=1 \
      --gtest_filter="${GRANSHOCK_GPU_CHECK_FILTER:-*}") || failed_programs=1
  done
  return $failed_programs
}
export -f test_programs
read -r -a test_args <<<"${GRANSHOCK_GPU_CHECK_TESTS:-}"
if [ -n "${GRANSHOCK_GPU_CHECK_PROGRAMS:-}" ]; then
  export GRANSHOCK_GPU_CHECK_PROGRAMS GRANSHOCK_GPU_CHECK_FILTER
  step tests 110 test_programs
  row "$(grep -sE '^\[  (PASSED|FAILED)  \]' "$out/tests.log" | tr '\n' ' ' | cut -c1-300)"
else
  step tests 110 ctest --test-dir "$build" -j $((jobs > 1 ? jobs / 2 : 1)) --timeout 100 \
    "${test_args[@]}"
  row "$(grep -sE 'tests passed|No tests were found' "$out/tests.log" | tail -n 1)"
fi

# 4. The gas benchmark (sigma 0.15 m/s, as docs/benchmarks.md): particle-steps per
# second, and the ratio to the 2-core host's in the same case (the reference's "bench").
host_rate() {  # CASE: the reference's particle-steps/s, or nothing
  [ -f "$reference" ] && $python -c 'import json, sys
r = json.load(open(sys.argv[1])).get("bench", {}).get(sys.argv[2])
print("%.3g" % r if r else "")' "$reference" "$1"
}
for case in "32000 0.1 10" "32000 0.5 10" "2000000 0.1 20" "2000000 0.5 20"; do
  read -r n phi box <<<"$case"
  name=gas_${n}_phi_$phi
  step "$name" "$box" "$bench" --particles "$n" --phi "$phi" --sigma 0.15 --repeats 1 \
    --min-seconds 1 --warmup-steps 20 --warmup-seconds 0.5 --min-cpu-share 0 \
    --json "$out/$name.json"
  rate=$($python -c 'import json, sys
print("%.3g" % json.load(open(sys.argv[1]))["results"][0]["median"])' "$out/$name.json" 2>/dev/null)
  host=$(host_rate "$name")
  if [ -n "$rate" ] && [ -n "$host" ]; then
    row "$rate ps/s; host (2 cores) $host ps/s, ratio $(awk -v a="$rate" -v b="$host" 'BEGIN {printf "%.2f", a / b}')"
  else
    row "${rate:+$rate ps/s}${rate:-$(log_tail "$name")}"
  fi
done

# 5. The default scene and a paper case for 0.05 s (the paper case with the inflow's
# Mach number as inserted, as tests/reference/check_bitwise.sh, to skip the inlet
# calibration), each then digested for the comparison.
scene_run() {  # NAME SCENE SETTINGS...
  local name=$1 scene=$2
  shift 2
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  "$granshock" run "$scene" --out "$out/$name" --quiet "${sets[@]}" || return
  [ "$digests" = deferred ] || digest_run "$name"
}
digest_run() {  # NAME
  $python "$here/gpu_check_compare.py" digest "$out/$1" >"$out/$1.json"
}
scene_result() {  # NAME
  $python -c 'import json, sys; d = json.load(open(sys.argv[1]))
print("%d particles, %.3g ps/s, %d list builds" % (d["particles_final"],
      d["particle_steps_per_second"], d["list_builds"]))' "$out/$1/summary.json" 2>/dev/null ||
    log_tail "$1"
}
export -f scene_run digest_run
export digests
default_scene=(scenes/default.toml time.duration=0.05 time.production_start=0.025)
paper_case=(scenes/paper/d50_u1000.toml inflow.mach_at=inserted time.duration=0.05
  time.production_start=0.025 output.snapshot_interval=0.025 output.checkpoint_interval=0.025)
step default_scene 40 scene_run default_scene "${default_scene[@]}"
row "$(scene_result default_scene)"
step paper_d50_u1000 40 scene_run paper_d50_u1000 "${paper_case[@]}"
row "$(scene_result paper_d50_u1000)"
# The reference also holds the host's field totals for two other seeds: a run that left
# the host's trajectory may differ from it by what another seed does (gpu_check_compare.py).
if [ "$mode" = record ]; then
  for seed in 2 3; do
    step "default_scene_seed$seed" 40 scene_run "default_scene_seed$seed" \
      "${default_scene[@]}" "scene.seed=$seed"
    row "$(scene_result "default_scene_seed$seed")"
    step "paper_d50_u1000_seed$seed" 40 scene_run "paper_d50_u1000_seed$seed" \
      "${paper_case[@]}" "scene.seed=$seed"
    row "$(scene_result "paper_d50_u1000_seed$seed")"
  done
fi

# Without h5py here the digests wait for the host: the files they read, packed.
if [ "$digests" = deferred ]; then
  packed=()
  for name in "${scene_runs[@]}"; do
    for f in checkpoint.h5 run.h5 summary.json; do
      [ -f "$out/$name/$f" ] && packed+=("$name/$f")
    done
  done
  [ ${#packed[@]} -eq 0 ] || tar -czf "$out/deferred.tar.gz" -C "$out" "${packed[@]}"
fi

# 6. Each run against the host's (the reference's "runs").
compare_run() {  # NAME
  $python - "$reference" "$1" >"$out/$1.reference.json" <<'PY' &&
import json, sys
print(json.dumps(json.load(open(sys.argv[1]))["runs"][sys.argv[2]]))
PY
    $python "$here/gpu_check_compare.py" compare "$out/$1.reference.json" "$out/$1.json"
}
export -f compare_run
if [ "$mode" = record ]; then
  step record 5 $python - "$out" "$reference" "$(cut -d' ' -f1-3 /proc/loadavg)" <<'PY'
import datetime, json, os, sys
out, reference, load = sys.argv[1:4]
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
cases = ("gas_32000_phi_0.1", "gas_32000_phi_0.5", "gas_2000000_phi_0.1", "gas_2000000_phi_0.5")
measured = {name: float("%.3g" % json.load(open(f"{out}/{name}.json"))["results"][0]["median"])
            for name in cases}
# The ratios' host rates stay those the reference has (measured on an idle host,
# docs/benchmarks.md): a loaded recording machine understates them. This recording's own
# rates are kept beside them, with the load it ran under.
old = json.load(open(reference)) if os.path.exists(reference) else {}
bench = old.get("bench") or dict(measured, source="gpu_check.sh --record")
runs = {name: json.load(open(f"{out}/{name}.json")) for name in ("default_scene", "paper_d50_u1000")}
for name, run in runs.items():
    run["other_seeds"] = [
        {path: t["sum"] for path, t in json.load(open(f"{out}/{name}_seed{seed}.json"))["field_totals"].items()}
        for seed in (2, 3)]
recorded = {"date": datetime.date.today().isoformat(), "cpu": cpu, "cores": os.cpu_count(),
            "load_average": load, "bench": measured}
json.dump({"bench": bench, "recorded": recorded, "runs": runs}, open(reference, "w"),
          indent=1, sort_keys=True)
print(f"recorded {os.path.basename(reference)}: runs {', '.join(runs)}; rates {measured}")
PY
  row "$(log_tail record)"
else
  for name in "${scene_runs[@]}"; do
    if [ "$mode" = finish ]; then
      step "digest_$name" 20 digest_run "$name"
      row "$(scene_result "$name")"
    fi
    if [ "$digests" = deferred ]; then
      step "compare_$name" 5 true
      [ "$step_status" = skipped ] || step_status=DEFERRED
      row "no h5py in $python: the digest waits for the host (--finish)"
      continue
    fi
    step "compare_$name" 5 compare_run "$name"
    row "$(tail -n 1 "$out/compare_$name.log" 2>/dev/null | cut -c1-400)"
  done
fi

# The table (also in $out/table.md).
{
  echo "granshock device check ($mode), $(date -u +%Y-%m-%d), $(uname -n), $jobs cores"
  echo
  echo "| step | status | s | box s | result |"
  echo "|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "total $(($(date +%s) - start_all)) s (boxes: $total_box s x $factor); logs in $out"
  if [ "$deferred" = 1 ]; then
    echo "digests deferred: bring $out/deferred.tar.gz to a machine whose Python has h5py," \
      "put it in a folder DIR and run apps/bench/gpu_check.sh --finish DIR there"
  fi
} | tee "$out/table.md"
[ "$failed" = 1 ] && exit 1
[ "$deferred" = 1 ] && exit 3
exit 0

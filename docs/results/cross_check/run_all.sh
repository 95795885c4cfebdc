#!/usr/bin/env bash
# The cross-check of README.md here, from the repository root with granshock built in
# build/ and Debian's lammps installed (apps/bench/lammps/install_lammps.sh):
#
#   docs/results/cross_check/run_all.sh RUNS_DIR [CASE ...]   (CASE: small, d10, d10_seed2,
#   d50, d10_long, d10_long_seed2, d50_long; default: small d10 d10_seed2)
#
# For each case: granshock's run (1 thread), LAMMPS on the same scene with granshock's
# inflow (run_lammps.sh, 1 rank), granshock's snapshots written as a LAMMPS dump with the
# map of the run's resolved scene (snapshots_to_dump.py), `granshock fields --from-dump`
# on both dumps with that map, and compare.py's table and figures into this folder.
# Runs at niceness 10 (NICE); the finished steps of a case are skipped. LMP_RANKS (default
# 1): LAMMPS' MPI ranks (its thermostat draws per rank, so another count is another
# realisation of the same inflow).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
runs=$1
shift
cases=("${@:-small d10 d10_seed2}")
read -r -a cases <<<"${cases[*]}"
granshock=${GRANSHOCK:-$root/build/apps/granshock/granshock}
mkdir -p "$runs"

run_case() {
  local name=$1 scene=$2
  shift 2
  local sets=("$@")
  if [[ ! -f $runs/gs_$name/summary.json ]]; then
    local t0=$SECONDS
    OMP_NUM_THREADS=1 OMP_PROC_BIND=false nice -n "${NICE:-10}" "$granshock" run "$scene" \
      --out "$runs/gs_$name" --overwrite --quiet --no-figures --backend-switch off "${sets[@]}"
    echo $((SECONDS - t0)) > "$runs/gs_$name/wall_seconds"
  fi
  # LAMMPS gets the sigma granshock used (calibrated where the scene gives inflow.mach).
  # SIGMA_FROM: the granshock run whose sigma LAMMPS gets (default this case's).
  local sigma
  sigma=$(/usr/bin/python3 -c 'import json, sys; print(repr(json.load(open(sys.argv[1]))["inflow_sigma"]))' \
    "$runs/${SIGMA_FROM:-gs_$name}/summary.json")
  if [[ ! -f $runs/lmp_$name/wall_seconds ]]; then
    SIGMA=$sigma SEED=${SEED:-1} REFILL_BLOCK=40 DUMP_EVERY=${DUMP_EVERY:-2.5e-4} "$here/run_lammps.sh" "${LMP_RANKS:-1}" "$runs/lmp_$name" \
      "$scene" "${sets[@]}"
  fi
  "$here/snapshots_to_dump.py" "$runs/gs_$name" "$runs/gs_${name}_snap.dump" "$runs/${name}_map.toml"
  local what
  for what in ${WHAT:-gs lmp}; do
    local dump=$runs/gs_${name}_snap.dump
    [[ $what == lmp ]] && dump=$runs/lmp_$name/frames.dump
    nice -n "${NICE:-10}" "$granshock" fields --from-dump lammps "$dump" \
      --map "$runs/${name}_map.toml" --out "$runs/${what}_${name}_from_dump" --no-figures
  done
  if [[ ${WHAT:-gs lmp} == lmp ]]; then
    /usr/bin/python3 "$here/compare.py" "$here/$name" "granshock run, seed 2=$runs/gs_$name" \
      "LAMMPS seed 2, --from-dump=$runs/lmp_${name}_from_dump"
  else
    /usr/bin/python3 "$here/compare.py" "$here/$name" "granshock run=$runs/gs_$name" \
      "LAMMPS, --from-dump=$runs/lmp_${name}_from_dump" \
      "granshock snapshots, --from-dump=$runs/gs_${name}_from_dump"
  fi
}

# paper_case NAME SCENE WIDTH END FRAME CHECKPOINT [--set ...]: scenes/paper/SCENE.toml
# narrowed to WIDTH m and END s long, [0.35, END] s averaged, granshock's snapshots and
# LAMMPS' frames every FRAME s, checkpoints every CHECKPOINT s.
paper_case() {
  local name=$1 scene=$2 width=$3 end=$4 frame=$5 checkpoint=$6
  shift 6
  DUMP_EVERY=$frame run_case "$name" "$root/scenes/paper/$scene.toml" "$@" \
    --set "domain.width=$width" --set "time.duration=$end" --set time.production_start=0.35 \
    --set "output.snapshot_interval=$frame" --set "output.checkpoint_interval=$checkpoint"
}

for c in "${cases[@]}"; do
  case $c in
    small) run_case small "$here/small.toml" ;;
    # The paper's D = 10 d, U = 1 m/s case narrowed to 100 d and shortened to 0.65 s.
    d10) paper_case d10 d10_u1000 0.1 0.65 0.00025 0.65 ;;
    # A second realisation: granshock with seed 2 (it recalibrates sigma), LAMMPS with
    # seed 2 and the sigma of granshock's seed-1 run; only LAMMPS' dump is analysed.
    d10_seed2) SIGMA_FROM=gs_d10 SEED=2 WHAT=lmp paper_case d10_seed2 d10_u1000 0.1 0.65 \
      0.00025 0.65 --set scene.seed=2 ;;
    # The paper's D = 50 d, U = 1 m/s case narrowed to 200 d (the cylinder a quarter of
    # the width) and shortened like d10.
    d50) paper_case d50 d50_u1000 0.2 0.65 0.00025 0.65 ;;
    # d10 and d50 with a four times longer window: whether the codes' differences outlast
    # the wandering of a 0.3 s window; d10_long's second realisation as d10_seed2 is d10's.
    d10_long) paper_case d10_long d10_u1000 0.1 1.65 0.0005 0.25 ;;
    d10_long_seed2) SIGMA_FROM=gs_d10_long SEED=2 WHAT=lmp paper_case d10_long_seed2 \
      d10_u1000 0.1 1.65 0.0005 0.25 --set scene.seed=2 ;;
    d50_long) paper_case d50_long d50_u1000 0.2 1.65 0.001 0.25 ;;
    *) echo "unknown case $c (small, d10, d10_seed2, d50, d10_long, d10_long_seed2," \
      "d50_long)" >&2
      exit 2 ;;
  esac
done

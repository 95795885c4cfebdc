# shellcheck shell=bash
# Shared by the scripts in apps/bench (sourced, not run).

# Prints the LAMMPS binary: $LMP if set, else the first of lmp (Debian's name),
# lmp_mpi, lmp_serial on PATH. Fails when there is none.
find_lmp() {
  if [[ -n "${LMP:-}" ]]; then
    command -v "$LMP"
    return
  fi
  local name
  for name in lmp lmp_mpi lmp_serial; do
    if command -v "$name"; then return 0; fi
  done
  echo "no LAMMPS binary (lmp, lmp_mpi or lmp_serial) on PATH: run" \
    "apps/bench/lammps/install_lammps.sh, or set LMP" >&2
  return 1
}

# Prints the version line of a LAMMPS binary, e.g. "29 Sep 2021 - Update 2".
lmp_version() {
  "$1" -h </dev/null | sed -n 's/^Large-scale Atomic\/Molecular Massively Parallel Simulator - //p'
}

# Whether a LAMMPS binary has the GRANULAR package (pair_style granular, fix
# wall/gran/region). The help text is read whole first: in `lmp -h | grep -q` under
# `set -o pipefail`, grep stops at the first match, lmp dies of SIGPIPE writing the rest,
# and the pipeline fails although the package is there.
lmp_has_granular() {
  local help
  help=$("$1" -h </dev/null 2>&1) || true
  grep -qw GRANULAR <<<"$help"
}

# Prints the granshock binary: $GRANSHOCK, else <repo>/build/apps/granshock/granshock.
find_granshock() {
  local root
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
  local bin=${GRANSHOCK:-$root/build/apps/granshock/granshock}
  if [[ ! -x $bin ]]; then
    echo "no granshock binary at $bin: build the repository (cmake --build build) or set" \
      "GRANSHOCK" >&2
    return 1
  fi
  echo "$bin"
}

# Heavy commands run at niceness $NICE (default 10): these machines are often shared,
# and on an idle machine the niceness changes nothing.
run_nice() {
  nice -n "${NICE:-10}" "$@"
}

# A timed leg of granshock's SCENE: WARMUP steps, then STEPS timed ones with field sampling
# from the warm-up's end. Sets dt (the scene's time step) and times (the --set options).
timed_leg_times() {
  local scene=$1 warmup=$2 steps=$3
  dt=$(/usr/bin/python3 -c 'import sys, tomllib; print(repr(tomllib.load(open(sys.argv[1], "rb"))["time"]["dt"]))' "$scene")
  times=(--set "time.duration=$(/usr/bin/python3 -c "print(repr(($warmup + $steps) * $dt))")"
    --set "time.production_start=$(/usr/bin/python3 -c "print(repr($warmup * $dt))")")
}

# mpirun for RANKS processes of one thread each, niced. Open MPI refuses root without
# --allow-run-as-root and more ranks than cores without --oversubscribe.
lammps_mpirun() {
  local ranks=$1
  shift
  OMP_NUM_THREADS=1 run_nice mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$@"
}

# Particle-steps per second from a LAMMPS log: ATOMS (default: the atoms at the end) x
# steps / seconds of the last "Loop time of T on P procs for S steps with N atoms" line.
loop_rate() {
  awk -v atoms="${2:-}" '/^Loop time of/ { t = $4; s = $9; n = $12 } END {
    if (t == "") { print "no Loop time line" > "/dev/stderr"; exit 1 }
    if (atoms != "") n = atoms
    printf "%.4g\n", n * s / t }' "$1"
}

# Warns on stderr when a LAMMPS run got less than 90 % of its cores ("CPU use" line):
# other processes competed for them and the rate measures the machine's load.
warn_if_disturbed() {
  awk '/% CPU use with/ { u = $1 + 0; if (u < 90)
    printf "warning: LAMMPS got %s CPU use: the machine was busy, the rate is not valid\n", \
      $1 > "/dev/stderr" }' "$1"
}

#!/usr/bin/env bash
# LAMMPS on granshock_bench_gas's case: a homogeneous 2-D granular gas of the paper's
# mixture in a periodic square box (gas_data.py), granshock's contact law
# (contact_law.py: hertz, e = 0.5 through the tsuji input, frictionless), dt = 5e-7 s,
# Verlet skin 0.3 d checked every step, LAMMPS' default atom sorting. Prints the
# particle-steps per second of the timed run (atoms x steps / "Loop time"), which
# excludes LAMMPS' setup (reading the data file, the first neighbour list).
#
# Usage: bench_gas.sh PHI N STEPS RANKS     e.g. bench_gas.sh 0.1 32000 5000 1
#   N is rounded to a full square lattice as in granshock (32000 -> 32041). At sigma
#   0.15 m/s the list is rebuilt about every 450 steps: STEPS >= 5000 times ten builds
#   (2-4 s for N = 32000 on one core).
# Environment: SIGMA (velocity standard deviation per component, default 0.15 m/s;
#   granshock_bench_gas's default is --sigma 1.0, pass the same to both), LMP, NICE
#   (niceness, default 10), KEEP (a folder to keep the input, data file and log in).
# Output: progress on stderr, the particle-steps/s alone on the last line of stdout.
#
# LAMMPS runs RANKS MPI processes of one thread each (Debian's build has no OPENMP
# package, so MPI is its only parallelism); compare with granshock at as many threads.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/common.sh"
if (($# != 4)); then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' >&2
  exit 2
fi
phi=$1 n=$2 steps=$3 ranks=$4
sigma=${SIGMA:-0.15}
lmp=$(find_lmp)
work=${KEEP:-$(mktemp -d)}
mkdir -p "$work"
[[ -n ${KEEP:-} ]] || trap 'rm -rf "$work"' EXIT

"$here/gas_data.py" "$phi" "$n" "$sigma" "$work/gas.data"
"$here/contact_law.py" pairs 0.5 > "$work/pairs.lmp"
cat > "$work/gas.in" <<EOF
# granshock_bench_gas's gas in LAMMPS (apps/bench/lammps/bench_gas.sh)
units si
dimension 2
boundary p p p
atom_style sphere
# pair granular needs the ghosts' velocities
comm_modify vel yes
read_data gas.data
pair_style granular
include pairs.lmp
# skin 0.3 d, checked every step (granshock's Verlet list)
neighbor 0.0003 bin
neigh_modify delay 0 every 1 check yes
fix integrate all nve/sphere
fix plane all enforce2d
timestep 5e-7
thermo $steps
run $steps
EOF
echo "LAMMPS $(lmp_version "$lmp"), $ranks rank(s), phi $phi, sigma $sigma m/s, $steps steps" >&2
(cd "$work" && lammps_mpirun "$ranks" "$lmp" -in gas.in -log gas.log -screen none)
grep -E '^Loop time|CPU use|^Neighbor list builds' "$work/gas.log" >&2
warn_if_disturbed "$work/gas.log"
loop_rate "$work/gas.log"

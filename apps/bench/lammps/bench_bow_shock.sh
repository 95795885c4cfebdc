#!/usr/bin/env bash
# LAMMPS on granshock's default scene (scenes/default.toml), started from granshock's own
# state at t = 0.1 s: the paper's mixture in a 150 d x 200 d channel, periodic in x, past
# a fixed aluminium cylinder of 20 d at (75 d, 120 d), dt = 2e-7 s, granshock's contact law
# (contact_law.py), skin 0.3 d checked every step. Prints particle-steps per second of
# the timed run (mean of the atoms at start and end x steps / "Loop time"). Run
# apps/bench/bench_bow_shock.sh for granshock's number on the same scene.
#
# Usage: bench_bow_shock.sh RANKS STEPS     e.g. bench_bow_shock.sh 2 20000
# Environment: STATE (a granshock run directory whose last snapshot is the start; default:
#   made once by running the scene to 0.1 s and kept in <repo>/build-bench/bow_shock_state),
#   GRANSHOCK, LMP, NICE (default 10), KEEP (a folder to keep the input and log in),
#   DUMP (a file: LAMMPS writes `dump custom` frames id type x y z vx vy vz there every
#   DUMP_EVERY steps, default 1000, for `granshock fields --from-dump lammps`; docs/fields.md).
# Output: progress on stderr, the particle-steps/s alone on the last line of stdout.
#
# How the scene maps onto LAMMPS:
# - Cylinder: region cylinder with open caps, `side out`, and one fix wall/gran/region per
#   species (granshock's particle-obstacle Y* differs by species; a LAMMPS wall has one
#   coefficient set). Open caps make LAMMPS use R_eff = r like granshock (contact_law.py).
# - Outflow at y = 200 d and loss through y = 0: boundary f in y; LAMMPS drops atoms that
#   leave the box at the next neighbour-list build, and `thermo_modify lost ignore` lets it
#   go on. granshock deletes them at the same boundaries.
# - No inflow. fix deposit inserts one particle per event with uniform (not Gaussian)
#   velocities, fix pour is a gravity hopper; neither reproduces granshock's strip
#   insertion, and over a short run inflow hardly matters: the flux is
#   phi W U / (pi r^2) = 19 100 particles/s, 76 particles over 20 000 steps (4 ms), 2 % of
#   the 3 900 in the channel, while the inlet side empties by U t = 4 d. The script prints
#   the numbers of each run. Keep STEPS at 50 000 or fewer (10 ms, 5 % of the particles).
# - No field sampling or output in LAMMPS; granshock's rate includes its sampling every
#   50 steps and its outputs, a few percent of its time.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../../.." && pwd)
source "$here/common.sh"
if (($# != 2)); then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' >&2
  exit 2
fi
ranks=$1 steps=$2
lmp=$(find_lmp)
work=${KEEP:-$(mktemp -d)}
mkdir -p "$work"
[[ -n ${KEEP:-} ]] || trap 'rm -rf "$work"' EXIT

state=${STATE:-$root/build-bench/bow_shock_state}
if [[ ! -f $state/summary.json ]]; then
  # The steady state: the default scene run to 0.1 s (a minute or two on 2 cores).
  # STATE given but unfinished is an error, the default is (re)made.
  [[ -z ${STATE:-} ]] || { echo "no finished granshock run in $state" >&2; exit 1; }
  echo "making the start state: granshock run scenes/default.toml to t = 0.1 s in $state" >&2
  mkdir -p "$(dirname "$state")"
  OMP_WAIT_POLICY=passive OMP_PROC_BIND=false \
    run_nice "$(find_granshock)" run "$root/scenes/default.toml" --out "$state" --overwrite \
      --quiet --set time.duration=0.1 --set time.production_start=0.05 >&2
fi
"$here/bow_data.py" "$state" "$work/bow.data" > "$work/scene.lmp"
"$here/contact_law.py" pairs 0.5 > "$work/pairs.lmp"
"$here/contact_law.py" walls 0.5 cyl > "$work/walls.lmp"
dump_lines=""
if [[ -n ${DUMP:-} ]]; then
  dump_file=$(cd "$(dirname "$DUMP")" && pwd)/$(basename "$DUMP")
  dump_lines="dump frames all custom ${DUMP_EVERY:-1000} $dump_file id type x y z vx vy vz
dump_modify frames sort id"
fi
cat > "$work/bow.in" <<EOF
# granshock's default scene in LAMMPS (apps/bench/lammps/bench_bow_shock.sh)
units si
dimension 2
boundary p f p
atom_style sphere
# pair granular needs the ghosts' velocities
comm_modify vel yes
read_data bow.data
include scene.lmp
group steel type 1
group aluminium type 2
pair_style granular
include pairs.lmp
region cyl cylinder z \${cx} \${cy} \${cr} INF INF open 1 open 2 side out units box
include walls.lmp
neighbor \${skin} bin
neigh_modify delay 0 every 1 check yes
fix integrate all nve/sphere
fix plane all enforce2d
timestep \${dt}
thermo_style custom step atoms ke
${dump_lines}
thermo_modify lost ignore norm no
thermo $steps
run $steps
print "INFLOW_MISSED \$(v_flux * v_dt * $steps)"
EOF
echo "LAMMPS $(lmp_version "$lmp"), $ranks rank(s), $steps steps from $(head -1 "$work/scene.lmp" | cut -c3-)" >&2
(cd "$work" && lammps_mpirun "$ranks" "$lmp" -in bow.in -log bow.log -screen none)
read -r n0 n1 < <(awk '/^Step/ { getline a; getline b; split(a, x); split(b, y)
                                   print x[2], y[2] }' "$work/bow.log")
echo "particles $n0 -> $n1 (left the box: $((n0 - n1)))" >&2
awk '/^INFLOW_MISSED/ { printf "granshock would have inserted about %.0f\n", $2 }' "$work/bow.log" >&2
grep -E '^Loop time|CPU use|^Neighbor list builds' "$work/bow.log" >&2
warn_if_disturbed "$work/bow.log"
loop_rate "$work/bow.log" "$(((n0 + n1) / 2))"

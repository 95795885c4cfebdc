#!/usr/bin/env bash
# One process with 2 threads against 2 MPI processes with 1 thread each, on the same state
# of a scene (docs/scaling.md): the scene runs to WARMUP_STEPS in one process and stops
# with a checkpoint; each configuration then resumes a copy of that checkpoint for STEPS
# timed steps (a checkpoint resumes on any number of processes, bitwise), REPEATS times,
# the configurations interleaved so that a change in the machine's load hits all alike.
# summary.json gives each leg's particle-steps/s (field sampling and outputs included)
# and, under mpirun, the halo's share of each rank's wall time and the particles per rank.
#
# Usage: mpi_scaling.sh [STEPS] [WARMUP_STEPS] [REPEATS] [SCENE]
#   (defaults 20000, 500000 = 0.1 s of the default scene, 5, scenes/default.toml)
# Environment: GRANSHOCK (binary), MPIEXEC (default mpirun), NICE (default 10), CONFIGS
#   (default: threads2 and ranks2_{y,x}_{equal,work}, and ranks2_y_particles; a
#   configuration ranks2_AXIS_BALANCE runs with --slabs AXIS --balance BALANCE, threads1
#   is one process on one thread, threads2_equal two threads with equal shares of the
#   particles instead of shares by time: --thread-shares).
# Output: a Markdown table on stdout (medians; ratios to one process per repeat, then
# their median), progress on stderr.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/lammps/common.sh"  # find_granshock, run_nice, timed_leg_times
steps=${1:-20000}
warmup=${2:-500000}
repeats=${3:-5}
scene=${4:-$root/scenes/default.toml}
granshock=$(find_granshock)
mpiexec=${MPIEXEC:-mpirun}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Spinning threads, as apps/bench/bench_gas and bench_bow_shock.sh time them.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-active} OMP_PROC_BIND=${OMP_PROC_BIND:-false}

timed_leg_times "$scene" "$warmup" "$steps"  # sets dt and times
echo "warming up: $warmup steps of $scene in one process (dt = $dt s)" >&2
OMP_NUM_THREADS=2 run_nice "$granshock" run "$scene" --out "$work/warm" --quiet "${times[@]}" \
  --stop-after-steps "$warmup" >&2

read -r -a configs <<<"${CONFIGS:-threads2 ranks2_y_equal ranks2_y_particles ranks2_y_work ranks2_x_equal ranks2_x_work}"
[ "${configs[0]}" = threads2 ] || { echo "mpi_scaling.sh: CONFIGS must start with threads2" >&2; exit 2; }
for ((r = 1; r <= repeats; r++)); do
  for c in "${configs[@]}"; do
    out=$work/$c.$r
    cp -r "$work/warm" "$out"
    case $c in
    threads[12]) OMP_NUM_THREADS=${c#threads} run_nice "$granshock" run "$scene" --out "$out" \
      --resume --quiet "${times[@]}" >&2 ;;
    threads2_equal) OMP_NUM_THREADS=2 run_nice "$granshock" run "$scene" --out "$out" --resume \
      --quiet --thread-shares equal "${times[@]}" >&2 ;;
    ranks2_*_*)
      axis=${c#ranks2_} && axis=${axis%_*}
      OMP_NUM_THREADS=1 run_nice "$mpiexec" -np 2 --bind-to core "$granshock" run "$scene" \
        --out "$out" --resume --quiet --slabs "$axis" --balance "${c##*_}" "${times[@]}" >&2 ;;
    *) echo "mpi_scaling.sh: unknown configuration $c" >&2; exit 2 ;;
    esac
    echo "repeat $r, $c: $(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["particle_steps_per_second"])' "$out/summary.json") particle-steps/s" >&2
  done
done

/usr/bin/python3 - "$work" "$repeats" "$steps" "$warmup" "${configs[@]}" <<'PY'
import json, statistics, sys
work, repeats, steps, warmup, configs = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5:]
runs = {c: [json.load(open(f"{work}/{c}.{r}/summary.json")) for r in range(1, repeats + 1)]
        for c in configs}
base = [s["particle_steps_per_second"] for s in runs["threads2"]]
print(f"{steps} steps timed after {warmup}; medians of {repeats} repeats, interleaved")
print("(each configuration's particle-steps/s per repeat: "
      + "; ".join(f"{c}: " + ", ".join(f"{s['particle_steps_per_second']:.3g}" for s in runs[c])
                  for c in configs) + ")\n")
print("| configuration | particle-steps/s | ratio to 1 x 2 threads | halo share (per rank) "
      "| exchange at rebuilds | per-step max share | particles per rank | ghosts per rank "
      "| rebalances |")
print("|---|---|---|---|---|---|---|---|---|")
for c in configs:
    rate = [s["particle_steps_per_second"] for s in runs[c]]
    ratio = statistics.median(x / b for x, b in zip(rate, base))
    p = runs[c][-1].get("processes", {})
    def shares(key):
        return [statistics.median(s["processes"][key][k] for s in runs[c])
                for k in range(p.get("count", 1))] if p.get("count", 1) > 1 else []
    share, sync = shares("halo_share_per_rank"), shares("sync_share_per_rank")
    rebuild = shares("rebuild_exchange_share_per_rank")
    if c.startswith("threads"):
        label = {"threads1": "1 process x 1 thread", "threads2": "1 process x 2 threads",
                 "threads2_equal": "1 process x 2 threads, equal shares"}[c]
    else:
        axis, balance = c.split("_")[1:]
        label = (f"2 processes x 1 thread, slabs along {axis}, "
                 + ("equal" if balance == "equal" else f"balanced by {balance}"))
    print(f"| {label} | {statistics.median(rate):.3g} | {ratio:.3f} | "
          f"{', '.join(f'{x:.1%}' for x in share) or '-'} | "
          f"{', '.join(f'{x:.1%}' for x in rebuild) or '-'} | "
          f"{', '.join(f'{x:.1%}' for x in sync) or '-'} | {p.get('particles_per_rank', '-')} | "
          f"{p.get('ghosts_per_rank', '-')} | {p.get('rebalances', '-')} |")
PY

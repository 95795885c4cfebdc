#!/usr/bin/env bash
# The time step at which a bow-shock run stops being correct, against the limit the guard
# predicts (docs/stability.md): the scene run with --force at multiples of the guard's
# stable limit, over several seeds, each run classified by what granshock says about it.
#
# Usage: stability_ladder.sh [SCENE] [SEEDS] [MULTIPLES...]
#   SCENE      default scenes/default.toml, shortened to 0.05 s (fields over the last 0.025 s)
#   SEEDS      runs per multiple, seeds 1..SEEDS (default 3)
#   MULTIPLES  of the stable limit (default 0.9 1.1 1.5 2 2.5 3 4)
# Environment: GRANSHOCK (binary, default <repo>/build/apps/granshock/granshock), THREADS
#   (OpenMP threads, default 1), DURATION (simulated seconds, default 0.05).
# Output: a markdown table on stdout, one row per run: exit code, dt/t_c, the largest
#   warning (energy created, particles lost through the inlet) or the diagnosis, and the
#   inlet backflow fraction and phi_inf deviation from summary.json.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
scene=${1:-$root/scenes/default.toml}
seeds=${2:-3}
shift $(($# > 2 ? 2 : $#)) || true
multiples=("$@")
[ ${#multiples[@]} -gt 0 ] || multiples=(0.9 1.1 1.5 2 2.5 3 4)
granshock=${GRANSHOCK:-$root/build/apps/granshock/granshock}
duration=${DURATION:-0.05}
export OMP_NUM_THREADS=${THREADS:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

length=(--set time.duration="$duration" --set time.production_start="$(/usr/bin/python3 -c "print($duration / 2)")")
stable=$("$granshock" run "$scene" --out "$work/dry" --dry-run "${length[@]}" 2>/dev/null |
  sed -n 's/^# time.dt = .*stable limit \([0-9.e+-]*\) s$/\1/p')
[ -n "$stable" ] || { echo "stability_ladder.sh: no stable limit in the dry run" >&2; exit 1; }
echo "scene $scene, ${duration} s, guard's stable limit $stable s, $OMP_NUM_THREADS thread(s)"
echo
echo "| dt / stable limit | seed | exit | dt/t_c | what granshock said | inlet backflow | phi_inf deviation |"
echo "|---|---|---|---|---|---|---|"
for m in "${multiples[@]}"; do
  dt=$(/usr/bin/python3 -c "print(f'{$m * $stable:.6g}')")
  for seed in $(seq 1 "$seeds"); do
    out=$work/m${m}_s$seed
    rc=0
    "$granshock" run "$scene" --out "$out" --quiet --force "${length[@]}" --set time.dt="$dt" \
      --set scene.seed="$seed" --set output.sample_every=10 >"$out.log" 2>&1 || rc=$?
    said=$(grep -o -e "blew up at step [0-9]*" -e "pushed through the obstacle" \
      -e "creates energy" -e "left through the inlet" "$out.log" | sort -u | paste -sd ';' - ||
      true)
    # dt/t_c, backflow and phi_inf deviation from summary.json ("-" where the run stopped).
    IFS='|' read -r ratio backflow deviation < <(/usr/bin/python3 - "$out/summary.json" <<'PY'
import json, sys
try:
    s = json.load(open(sys.argv[1]))
except OSError:
    print("-|-|-")
    sys.exit()
dev = s.get("phi_inf_deviation")
print(f"{s['dt_over_tc']:.3f}|{s['inlet_backflow_fraction']:.3f}|"
      + (f"{dev:+.3f}" if dev is not None else "n/a"))
PY
)
    echo "| $m | $seed | $rc | $ratio | ${said:-nothing} | $backflow | $deviation |"
  done
done

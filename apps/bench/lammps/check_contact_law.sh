#!/usr/bin/env bash
# Checks that LAMMPS, set up by contact_law.py, integrates granshock's contact law: the
# same head-on collisions in both codes (`granshock collide` and a two-body LAMMPS run),
# compared by effective restitution e_eff and contact duration t_contact.
#
# Why this is a fair test: both codes integrate the same ODE with velocity Verlet, the
# dashpot seeing the half-step velocity, from the same start (collide's: gap 5 v dt,
# zero-momentum frame, dt = t_c/100). LAMMPS is given collide's dt and start, and its gap
# is interpolated to zero between steps exactly as collide does
# (cases/collision/head_on_collision.cpp). Any factor wrong in the translation (4/3,
# E_eff, alpha, R*, m*) shows up at the percent level; matching codes agree to rounding.
# The derivation of the tsuji input is in contact_law.py's docstring.
#
# Pairs: steel-steel (hertz/material, LAMMPS' own E_eff), steel-aluminium (explicit
# stiffness), and both species on the aluminium cylinder (fix wall/gran/region, as in
# bench_bow_shock.sh). The LAMMPS cylinder has diameter 10 d like collide's.
#
# Usage: check_contact_law.sh [SPEED] [E]   (defaults 1 m/s, 0.5)
# Environment: GRANSHOCK (granshock binary), LMP (LAMMPS binary), NICE (default 10), TOL (largest relative
#   difference accepted, default 1e-3). Measured at 0.1, 1 and 5 m/s, e = 0.5 and 0.9: the
#   particle pairs agree to 1e-15 and the wall impacts to 1.5e-6 (collide's gap of 5 v dt
#   closes exactly on a step, and the two codes' different formulas for the distance to
#   the cylinder round that first overlap to either side of zero); a wrong factor moves
#   e_eff by percents (the untranslated tsuji input e' = e = 0.5 gives e_eff = 0.617
#   instead of 0.501).
# Exit status 1 when any difference exceeds TOL.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/common.sh"
speed=${1:-1}
e=${2:-0.5}
tol=${TOL:-1e-3}
lmp=$(find_lmp)
granshock=$(find_granshock)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "LAMMPS $(lmp_version "$lmp") ($lmp); granshock $granshock"
echo "speed $speed m/s, e = $e, tsuji e' = $("$here/contact_law.py" tsuji "$e")"
"$here/contact_law.py" pairs "$e" > "$work/pairs.lmp"
"$here/contact_law.py" walls "$e" cyl > "$work/walls.lmp"

fail=0
for pair in steel-steel steel-aluminium steel-obstacle aluminium-obstacle; do
  run_nice "$granshock" collide --pair "$pair" --speed "$speed" --e "$e" > "$work/$pair.json"
  # LAMMPS input and data file with collide's dt and start.
  /usr/bin/python3 "$here/collision.py" input "$work/$pair.json" "$work/$pair"
  if ! (cd "$work" && run_nice "$lmp" -in "$pair.in" -log "$pair.log" -screen none); then
    tail -5 "$work/$pair.log" >&2
    exit 1
  fi
  if ! /usr/bin/python3 "$here/collision.py" compare "$work/$pair.json" \
    "$work/$pair.log" "$tol"; then
    fail=1
  fi
done
if ((fail)); then
  echo "FAIL: some difference exceeds $tol"
  exit 1
fi
echo "OK: all differences within $tol"

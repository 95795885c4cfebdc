#!/usr/bin/env bash
# Skipping the figures (docs/fields.md, "figures/"): `run --no-figures` and
# GRANSHOCK_FIGURES=0 write every output but figures/ and end with one note naming the
# command that draws them later; that command, run as the note says, draws them (figures
# are on by default). `fields --no-figures` draws none either; --quiet drops the note.
# Usage: no_figures.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
fail() {
  echo "FAIL: $*"
  status=1
}
# The tiny channel of tests/study/tiny.toml, 2 ms (10 000 steps), no progress lines.
tiny=(--set "domain.width=40 d" --set "domain.length=60 d" --set "obstacle.diameter=10 d"
  --set 'obstacle.centre=["20 d", "35 d"]' --set time.duration=0.002
  --set time.production_start=0.001 --set output.sample_every=20
  --set output.progress_interval=1000)
# A granshock on PATH, as the note names it.
mkdir "$dir/bin" && ln -s "$(realpath "$granshock")" "$dir/bin/granshock"
unset GRANSHOCK_FIGURES
# no_figures RUN_DIR WHAT: the analysis is there, the figures are not.
no_figures() {
  [ -s "$1/fields.h5" ] && [ -s "$1/summary.json" ] || fail "$2: no fields.h5 or summary.json"
  [ ! -e "$1/figures" ] || fail "$2: figures drawn: $(ls "$1/figures")"
}
# the_note ERR: the note's lines in ERR (compared with the one line expected).
the_note() { grep 'figures not drawn' "$1"; }
# redraw NOTE: runs the command the note names, with granshock on PATH.
redraw() {
  (PATH=$dir/bin:$PATH && eval "${1#*draw them later with: }") >"$dir/redraw.out" 2>&1 ||
    fail "the note's command failed: ${1#*with: }: $(tail -3 "$dir/redraw.out")"
}

# --no-figures, into a directory whose name the note must quote.
run="$dir/run one"
"$granshock" run "$scene" --out "$run" --no-figures "${tiny[@]}" >"$dir/out" 2>"$dir/err" ||
  fail "run --no-figures: $(cat "$dir/err")"
no_figures "$run" "run --no-figures"
note=$(the_note "$dir/err")
[ "$note" = "granshock: figures not drawn (--no-figures); draw them later with: granshock fields '$run'" ] ||
  fail "the note: $note"

# GRANSHOCK_FIGURES=0: the note says so, and its command turns the figures back on.
GRANSHOCK_FIGURES=0 "$granshock" run "$scene" --out "$dir/env" "${tiny[@]}" >"$dir/out" 2>"$dir/err" ||
  fail "run with GRANSHOCK_FIGURES=0: $(cat "$dir/err")"
no_figures "$dir/env" "GRANSHOCK_FIGURES=0"
env_note=$(the_note "$dir/err")
[ "$env_note" = "granshock: figures not drawn (GRANSHOCK_FIGURES=0); draw them later with: GRANSHOCK_FIGURES=1 granshock fields $dir/env" ] ||
  fail "the note: $env_note"

# --quiet: no note. `fields --no-figures`: none drawn, the note names `fields` again.
"$granshock" run "$scene" --out "$dir/quiet" --no-figures --quiet "${tiny[@]}" >"$dir/out" 2>"$dir/err" ||
  fail "run --no-figures --quiet: $(cat "$dir/err")"
no_figures "$dir/quiet" "run --no-figures --quiet"
! grep -q 'not drawn' "$dir/err" || fail "--quiet printed the note: $(cat "$dir/err")"
"$granshock" fields "$dir/quiet" --no-figures >"$dir/out" 2>"$dir/err" ||
  fail "fields --no-figures: $(cat "$dir/err")"
no_figures "$dir/quiet" "fields --no-figures"
[ "$(the_note "$dir/err")" = "granshock: figures not drawn (--no-figures); draw them later with: granshock fields $dir/quiet" ] ||
  fail "the note of fields --no-figures: $(cat "$dir/err")"

# The notes' commands draw the figures (figures on by default: GRANSHOCK_FIGURES unset).
if /usr/bin/python3 -c "import matplotlib, h5py, numpy" 2>/dev/null; then
  redraw "$note"
  redraw "$env_note"
  for d in "$run" "$dir/env"; do
    for png in solid_fraction temperature mach stagnation_profiles; do
      [ -s "$d/figures/$png.png" ] || fail "the note's command did not draw $d/figures/$png.png"
    done
  done
fi
[ $status -eq 0 ] && echo "PASS"
exit $status

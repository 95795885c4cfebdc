#!/usr/bin/env bash
# Every name of every choice, as `granshock info` lists them (core/choice_names.hpp), is
# accepted where a user gives it and comes back unchanged: `collide --model`,
# `--restitution-mode` and `--precision` (its JSON), each scene key in the resolved scene
# of a dry run, each option of `run` by a dry run, and in short runs that together take
# every name of the contact laws, precisions, restitution modes, field scatters and
# backend switches: summary.json's variant and backend switch, and the resolved scene
# stored in checkpoint.h5. Names come from the program, so a name added to a table is
# tested here without a change to this script.
# Usage: every_choice_name.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

"$granshock" info >"$dir/info.json" || { echo "FAIL: granshock info"; exit 1; }
# names WHAT: the names of the choice WHAT, space-separated.
names() {
  python3 -c 'import json, sys; print(" ".join(json.load(open(sys.argv[1]))["choices"][sys.argv[2]]))' \
    "$dir/info.json" "$1" || echo "FAIL: no choice '$1' in granshock info"
}
# nth K NAMES...: the (K mod count)-th of NAMES.
nth() { local k=$1; shift; local a=("$@"); echo "${a[$((k % ${#a[@]}))]}"; }

models=($(names "contact model")) modes=($(names "restitution mode"))
precisions=($(names precision)) scatters=($(names "field scatter"))
switches=($(names "backend switch"))
[ ${#models[@]} -ge 2 ] || fail "granshock info lists the contact models '${models[*]}'"

for model in "${models[@]}"; do
  out=$("$granshock" collide --pair steel-steel --speed 1 --model "$model" 2>&1) ||
    fail "collide --model $model: $out"
  grep -q "\"model\": \"$model\"" <<<"$out" || fail "collide --model $model says: $out"
  grep -q "\"variant\": \"[^\"]*/$model/" <<<"$out" || fail "collide --model $model ran: $out"
done
for mode in "${modes[@]}"; do
  out=$("$granshock" collide --pair steel-steel --speed 1 --restitution-mode "$mode" 2>&1) ||
    fail "collide --restitution-mode $mode: $out"
  grep -q "\"restitution_mode\": \"$mode\"" <<<"$out" ||
    fail "collide --restitution-mode $mode says: $out"
done
for precision in "${precisions[@]}"; do
  out=$("$granshock" collide --pair steel-steel --speed 1 --precision "$precision" 2>&1) ||
    fail "collide --precision $precision: $out"
  grep -q "\"variant\": \"[^\"]*/$precision/" <<<"$out" || fail "collide --precision $precision ran: $out"
done

# dry KEY NAME: a dry run with scene key KEY = NAME prints NAME under KEY's own name.
dry() {
  local out
  out=$("$granshock" run "$scene" --dry-run --out "$dir/never" --set "$1=\"$2\"" 2>&1) ||
    { fail "--set $1=$2: $out"; return; }
  grep -qx "${1##*.} = '$2'" <<<"$out" || fail "--set $1=$2: the resolved scene says
$(grep "^${1##*.} = " <<<"$out")"
}
for n in "${models[@]}"; do dry contact.model "$n"; done
for n in "${modes[@]}"; do dry contact.restitution_mode "$n"; done
for n in "${precisions[@]}"; do dry numerics.precision "$n"; done
for n in "${scatters[@]}"; do dry numerics.field_scatter "$n"; done
for n in $(names "mass definition"); do dry numerics.mass_definition "$n"; done
for n in $(names "mach reference"); do
  out=$("$granshock" run "$scene" --dry-run --out "$dir/never" --set "inflow.mach_at=\"$n\"" 2>&1) ||
    fail "--set inflow.mach_at=$n: $out"
done
# option WHAT FLAG: every name of WHAT passes FLAG's check.
option() {
  local n out
  for n in $(names "$1"); do
    out=$("$granshock" run "$scene" --dry-run --out "$dir/never" "$2" "$n" 2>&1) ||
      fail "run $2 $n: $out"
  done
}
option "slab axis" --slabs
option balance --balance
option "snapshot output" --snapshot-output
option "backend switch" --backend-switch

# Short runs, the k-th taking the k-th name of each choice (cycling), until every name of
# the longest list has run.
count=0
for list in models modes precisions scatters switches; do
  eval "n=\${#$list[@]}"
  [ "$n" -gt "$count" ] && count=$n
done
for ((k = 0; k < count; ++k)); do
  model=$(nth $k "${models[@]}") mode=$(nth $k "${modes[@]}")
  precision=$(nth $k "${precisions[@]}") scatter=$(nth $k "${scatters[@]}")
  switch=$(nth $k "${switches[@]}")
  run="$dir/run$k"
  what="run $k ($model, $mode, $precision, $scatter, $switch)"
  "$granshock" run "$scene" --out "$run" --quiet --backend-switch "$switch" \
    --set "contact.model=\"$model\"" --set "contact.restitution_mode=\"$mode\"" \
    --set "numerics.precision=\"$precision\"" --set "numerics.field_scatter=\"$scatter\"" \
    --set time.duration=0.0004 --set time.production_start=0.0002 \
    --set output.snapshot_interval=0.0002 --set output.series_interval=0.0001 \
    --set output.checkpoint_interval=0.0002 --set output.sample_every=10 \
    --no-figures >"$dir/out$k" 2>&1 || { fail "$what: $(tail -3 "$dir/out$k")"; continue; }
  grep -q "\"variant\": \"[^\"]*/$precision/$model/" "$run/summary.json" ||
    fail "$what: summary.json says $(grep '"variant"' "$run/summary.json")"
  if grep -q '"backend_switch"' "$run/summary.json"; then
    grep -q "\"mode\": \"$switch\"" "$run/summary.json" ||
      fail "$what: summary.json's backend switch is $(grep '"mode"' "$run/summary.json")"
  fi
  resolved=$(h5dump -d /scene/resolved "$run/checkpoint.h5") || { fail "$what: h5dump"; continue; }
  for pair in "model=$model" "restitution_mode=$mode" "precision=$precision" \
    "field_scatter=$scatter"; do
    grep -q "${pair%%=*} = '${pair#*=}'" <<<"$resolved" ||
      fail "$what: the checkpoint's scene lacks ${pair%%=*} = '${pair#*=}'"
  done
done
[ "$failed" = 0 ] && echo "PASS: every name of ${#models[@]} contact models and of every other choice"
exit $failed

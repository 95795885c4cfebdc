#!/usr/bin/env bash
# Every name of every choice, as `granshock info` lists them (core/choice_names.hpp,
# core/variant_names.hpp), is accepted where a user gives it and comes back unchanged.
# Round k takes the k-th name of each choice (cycling), until every name of the longest
# list has been given: `collide --model --restitution-mode --precision` (its JSON), a dry
# run with each scene key and each option of `run` (the resolved scene it prints), and a
# short run (summary.json's variant and backend switch, the resolved scene stored in
# checkpoint.h5). Names come from the program, so a name added to a table is tested here
# without a change to this script.
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
    "$dir/info.json" "$1" 2>/dev/null || fail "no choice '$1' in granshock info"
}
# law_keys MODEL FORM: the law's required keys (granshock info's contact_law_keys), each
# in the middle of its accepted range on a log scale, as collide options (FORM option:
# --stiffness V) or scene keys (FORM set: --set contact.stiffness=V).
law_keys() {
  python3 -c '
import json, math, sys
keys = json.load(open(sys.argv[1]))["contact_law_keys"][sys.argv[2]]
for k in keys:
    if k["default"] != "required":
        continue
    lo, hi = k["accepted"]
    value = "%g" % math.sqrt(lo * hi)
    name = k["key"].split(".", 1)[1]
    if sys.argv[3] == "option":
        print("--" + name.replace("_", "-"), value)
    else:
        print("--set", k["key"] + "=" + value)
' "$dir/info.json" "$1" "$2" 2>/dev/null || fail "no contact_law_keys for '$1' in granshock info"
}
models=($(names "contact model")) modes=($(names "restitution mode"))
precisions=($(names precision)) scatters=($(names "field scatter"))
masses=($(names "mass definition")) machs=($(names "mach reference"))
axes=($(names "slab axis")) balances=($(names balance))
outputs=($(names "snapshot output")) switches=($(names "backend switch"))
shares=($(names "thread shares"))
[ ${#models[@]} -ge 2 ] || fail "granshock info lists the contact models '${models[*]}'"

rounds=0
for list in models modes precisions scatters masses machs axes balances outputs switches shares; do
  eval "n=\${#$list[@]}"
  [ "$n" -gt "$rounds" ] && rounds=$n
done
# nth K NAMES...: the (K mod count)-th of NAMES.
nth() { local k=$1; shift; local a=("$@"); echo "${a[$((k % ${#a[@]}))]}"; }
# has TEXT LINE: whether TEXT holds LINE as a whole line.
has() { grep -qxF "$2" <<<"$1"; }

for ((k = 0; k < rounds; ++k)); do
  model=$(nth $k "${models[@]}") mode=$(nth $k "${modes[@]}")
  precision=$(nth $k "${precisions[@]}") scatter=$(nth $k "${scatters[@]}")
  mass=$(nth $k "${masses[@]}") mach=$(nth $k "${machs[@]}") axis=$(nth $k "${axes[@]}")
  balance=$(nth $k "${balances[@]}") output=$(nth $k "${outputs[@]}")
  switch=$(nth $k "${switches[@]}") share=$(nth $k "${shares[@]}")
  what="round $k ($model, $mode, $precision, $scatter, $mass, $mach, $axis, $balance, $output, $switch, $share)"

  out=$("$granshock" collide --pair steel-steel --speed 1 --model "$model" $(law_keys "$model" option) \
    --restitution-mode "$mode" --precision "$precision" 2>&1) || fail "$what: collide: $out"
  grep -q "\"model\": \"$model\"" <<<"$out" || fail "$what: collide says $out"
  grep -q "\"restitution_mode\": \"$mode\"" <<<"$out" || fail "$what: collide says $out"
  grep -q "\"variant\": \"[^\"]*/$precision/$model/" <<<"$out" || fail "$what: collide ran $out"

  scene_keys=(--set "contact.model=\"$model\"" $(law_keys "$model" set)
    --set "contact.restitution_mode=\"$mode\""
    --set "numerics.precision=\"$precision\"" --set "numerics.field_scatter=\"$scatter\"")
  out=$("$granshock" run "$scene" --dry-run --out "$dir/never" "${scene_keys[@]}" \
    --set "numerics.mass_definition=\"$mass\"" --set "inflow.mach_at=\"$mach\"" \
    --slabs "$axis" --balance "$balance" --snapshot-output "$output" \
    --backend-switch "$switch" --thread-shares "$share" 2>&1) || { fail "$what: dry run: $out"; continue; }
  for line in "model = '$model'" "restitution_mode = '$mode'" "precision = '$precision'" \
    "field_scatter = '$scatter'" "mass_definition = '$mass'"; do
    has "$out" "$line" || fail "$what: the dry run's resolved scene lacks $line"
  done

  run="$dir/run$k"
  "$granshock" run "$scene" --out "$run" --quiet --no-figures "${scene_keys[@]}" \
    --backend-switch "$switch" --thread-shares "$share" --set time.duration=0.0004 --set time.production_start=0.0002 \
    --set output.snapshot_interval=0.0002 --set output.series_interval=0.0001 \
    --set output.checkpoint_interval=0.0002 --set output.sample_every=10 \
    >"$dir/out$k" 2>&1 || { fail "$what: run: $(tail -3 "$dir/out$k")"; continue; }
  grep -q "\"variant\": \"[^\"]*/$precision/$model/" "$run/summary.json" ||
    fail "$what: summary.json says $(grep '"variant"' "$run/summary.json")"
  if grep -q '"backend_switch"' "$run/summary.json"; then
    grep -q "\"mode\": \"$switch\"" "$run/summary.json" ||
      fail "$what: summary.json's backend switch is $(grep '"mode"' "$run/summary.json")"
  fi
  if grep -q '"thread_shares"' "$run/summary.json"; then
    grep -q "\"mode\": \"$share\"" "$run/summary.json" ||
      fail "$what: summary.json's thread shares are $(grep -A1 '"thread_shares"' "$run/summary.json")"
  fi
  resolved=$(h5dump -d /scene/resolved "$run/checkpoint.h5") || { fail "$what: h5dump"; continue; }
  for line in "model = '$model'" "restitution_mode = '$mode'" "precision = '$precision'" \
    "field_scatter = '$scatter'"; do
    grep -qF "$line" <<<"$resolved" || fail "$what: the checkpoint's scene lacks $line"
  done
done
[ "$failed" = 0 ] && echo "PASS: every name of every choice ($rounds rounds)"
exit $failed

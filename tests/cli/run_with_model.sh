#!/usr/bin/env bash
# A short `granshock run` of a scene with another contact law (--set contact.model=MODEL):
# 4 ms of simulated time (20 000 steps of the default scene, a few seconds on 2 cores) must
# complete, and summary.json must name the law in the variant that ran. KEY=VALUE...: the
# law's own keys (contact.stiffness=... for linear).
# Usage: run_with_model.sh GRANSHOCK SCENE MODEL [KEY=VALUE...]
set -u
granshock=$1 scene=$2 model=$3
shift 3
law_keys=()
for kv in "$@"; do law_keys+=(--set "$kv"); done
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$granshock" run "$scene" --out "$dir/run" --quiet --set "contact.model=$model" "${law_keys[@]}" \
  --set time.duration=0.004 --set time.production_start=0.002 ||
  { echo "the run failed with exit code $?"; exit 1; }
grep -Eq "\"variant\": \"[^\"]*/$model/" "$dir/run/summary.json" ||
  { echo "summary.json does not name the $model law:"; grep variant "$dir/run/summary.json"; exit 1; }
grep -q '"completed": true' "$dir/run/summary.json" ||
  { echo "summary.json does not say the run completed"; exit 1; }
echo "$model run completed"

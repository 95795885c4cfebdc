#!/usr/bin/env bash
# granshock's gas benchmark side by side with a hand-written reference step (an OpenMP
# program outside this repository that advances the same 2-D steel/aluminium gas and
# prints "RESULT <variant> ... median <rate> ps/s"; docs/benchmarks.md). The two run in
# alternation, REPEATS times per case, so that both see the same machine; the script
# prints the medians and the ratio granshock / reference per case.
#
# Usage: compare_reference.sh REFERENCE.cpp|REFERENCE_BINARY [BUILD_DIR]
# Environment: REPEATS (default 5), THREADS (default 2), SECONDS_PER_RUN (default 2),
#   CASES (default "0.1:32000 0.5:32000 0.1:2000000 0.5:2000000", phi:N),
#   VARIANT (the reference's variant, default vl_1p), SIGMA (default 0.15 m/s, the
#   reference's initial velocity spread), SKIN (granshock's skin in d; default: its own),
#   ADAPTIVE=1 (granshock re-chooses its skin at each build, up to SKIN: --adaptive-skin),
#   PLACEMENT (granshock's start: lattice, random, or the default "match": random up to
#   phi 0.3 and the lattice above, as the reference starts; a lattice start at phi 0.1
#   leaves the lists nearly empty, docs/benchmarks.md, "The paper case against a random gas").
set -euo pipefail
reference=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
build=${2:-$here/../../build}
repeats=${REPEATS:-5}
threads=${THREADS:-2}
seconds=${SECONDS_PER_RUN:-2}
cases=${CASES:-"0.1:32000 0.5:32000 0.1:2000000 0.5:2000000"}
variant=${VARIANT:-vl_1p}
sigma=${SIGMA:-0.15}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [[ $reference == *.cpp ]]; then
  g++ -O3 -march=native -fopenmp -std=c++17 -o "$work/reference" "$reference"
  reference=$work/reference
fi
bench=$build/apps/bench/granshock_bench_gas
[[ -x $bench ]] || { echo "no $bench: build granshock first" >&2; exit 2; }
export OMP_NUM_THREADS=$threads OMP_PROC_BIND=close OMP_PLACES=cores SOL_CACHE=$work

reference_rate() {  # phi n -> particle-steps/s (one run)
  "$reference" bench "$variant" "$1" "$2" "$seconds" 1 2>/dev/null |
    awk '/^RESULT/ { for (k = 1; k <= NF; ++k) if ($k == "median") print $(k + 1) }'
}

granshock_rate() {  # phi n -> particle-steps/s (one repeat)
  local skin=()
  [[ -n ${SKIN:-} ]] && skin=(--skin "$SKIN")
  [[ ${ADAPTIVE:-0} == 1 ]] && skin+=(--adaptive-skin)
  local start=${PLACEMENT:-match}
  if [[ $start == match ]]; then
    start=lattice
    awk -v phi="$1" 'BEGIN { exit !(phi <= 0.3) }' && start=random
  fi
  "$bench" --phi "$1" --particles "$2" --sigma "$sigma" --repeats 1 --min-seconds "$seconds" \
    "${skin[@]}" --placement "$start" --json "$work/g.json" >/dev/null 2>&1
  /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results'][0]['median'])" \
    "$work/g.json"
}

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }

# ratio: of the two medians; per round: granshock / reference of each alternating pair
# (the machine's speed drifts between rounds, so their median is the steadier figure).
echo "| phi | N | $variant p-steps/s | granshock p-steps/s | ratio | per round | median of rounds |"
echo "|---|---|---|---|---|---|---|"
for c in $cases; do
  phi=${c%%:*} n=${c##*:}
  ref_rates="" gs_rates="" round_ratios=""
  for ((r = 1; r <= repeats; ++r)); do
    ref_rate=$(reference_rate "$phi" "$n")
    gs_rate=$(granshock_rate "$phi" "$n")
    ref_rates+=" $ref_rate" gs_rates+=" $gs_rate"
    round_ratios+=" $(awk -v a="$gs_rate" -v b="$ref_rate" 'BEGIN { printf "%.2f", a / b }')"
  done
  ref=$(echo "$ref_rates" | median) gs=$(echo "$gs_rates" | median)
  printf '| %s | %s | %.3g | %.3g | %.2f | %s | %.2f |\n' "$phi" "$n" "$ref" "$gs" \
    "$(awk -v a="$gs" -v b="$ref" 'BEGIN { print a / b }')" "${round_ratios# }" \
    "$(echo "$round_ratios" | median)"
done
echo "($repeats alternating repeats of ${seconds} s, $threads threads; reference variant $variant;" \
  "sigma $sigma m/s)"

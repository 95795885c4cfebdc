#!/usr/bin/env bash
# The certificate campaign's tables from its records (docs/results/certificate/README.md):
# for each study whose records hold the reference and two seeds of the scene, its trade
# table (trade.md, trade.csv, trade.json, pareto.png) beside the records. Reads nothing
# but the records: run it on a fresh clone.
# Usage: docs/results/certificate/make_tables.sh [--no-figures]
set -euo pipefail
cd "$(dirname "$0")/../../.."
for study in d50_u2375 d10_u0475 d100_u1000; do
  records=docs/results/certificate/$study
  if [ -s "$records/cases/reference/summary.json" ] && [ -s "$records/cases/scene/summary.json" ] &&
    [ -s "$records/cases/seed-2/summary.json" ]; then
    /usr/bin/python3 cases/tradeoff/trade_table.py "$records" "$records" "$@" >/dev/null
    echo "$records/trade.md"
  else
    echo "$records: no table yet (the reference and two seeds of the scene are not all recorded)"
  fi
done

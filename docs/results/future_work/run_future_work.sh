#!/bin/bash
# The future-work study (studies/future_work.toml), granshock built at commit 9d8b449, one
# thread (the paper cases ran on the other core). Run from the repository root (the
# measured run used a worktree of that commit, and set OMP_WAIT_POLICY=passive; the README
# says to leave it unset, as here).
# Usage: docs/results/future_work/run_future_work.sh [GRANSHOCK]
set -u
granshock=${1:-build/apps/granshock/granshock}
mkdir -p runs/future_work
start=$(date +%s)
OMP_NUM_THREADS=1 "$granshock" study studies/future_work.toml --out runs/future_work/study \
  >runs/future_work/study.log 2>&1
echo "rc=$? wall=$(( $(date +%s) - start )) s" >>runs/future_work/progress.txt

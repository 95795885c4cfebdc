#!/bin/bash
# The future-work study (studies/future_work.toml), granshock built at commit 9d8b449, from a
# worktree of that commit, one thread (the paper cases run on the other core).
cd /work/wt-fw
start=$(date +%s)
OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive /work/runs/future_work/granshock-bin study studies/future_work.toml --out /work/runs/future_work/study > /work/runs/future_work/study.log 2>&1
echo "rc=$? wall=$(( $(date +%s) - start )) s" >> /work/runs/future_work/progress.txt

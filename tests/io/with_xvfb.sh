#!/usr/bin/env bash
# Runs COMMAND under a virtual X server (xvfb-run -a), again up to twice more when the
# command could not reach the server: on a loaded machine pvbatch has been seen to connect
# before Xvfb accepted connections ("bad X server connection", then SIGABRT), which says
# nothing about the files the command checks. Any other failure is the command's own.
# Usage: with_xvfb.sh XVFB_RUN COMMAND...
set -u
xvfb_run=$1
shift
out=$(mktemp)
trap 'rm -f "$out"' EXIT
for attempt in 1 2 3; do
  "$xvfb_run" -a -s "-screen 0 640x480x24" "$@" >"$out" 2>&1
  code=$?
  if ! grep -q "bad X server connection" "$out"; then
    cat "$out"
    exit "$code"
  fi
  echo "with_xvfb.sh: attempt $attempt could not reach the X server; starting another" >&2
  sleep 2
done
cat "$out"
exit "$code"

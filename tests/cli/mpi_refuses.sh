#!/bin/bash
# `mpirun -np 2 granshock run SCENE`: each process would run the whole scene into the same
# directory. Both must refuse with exit code 2, the reason said once (by rank 0), and the
# run directory not created. Usage: mpi_refuses.sh MPIEXEC GRANSHOCK SCENE
set -u
mpiexec=$1 granshock=$2 scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$mpiexec" --oversubscribe -np 2 "$granshock" run "$scene" --out "$work/run" \
  >"$work/out" 2>"$work/err"
status=$?
cat "$work/err"
said=$(grep -c "started as 2 MPI processes" "$work/err")
[ "$status" -ne 0 ] || { echo "FAIL: exit status 0"; exit 1; }
[ "$said" -eq 1 ] || { echo "FAIL: the reason was said $said times, not once"; exit 1; }
[ ! -e "$work/run" ] || { echo "FAIL: the run directory was created"; exit 1; }
# The same program started without a launcher is not affected: info says so.
"$granshock" info | grep -q '"launched": false' || { echo "FAIL: info without mpirun"; exit 1; }
"$mpiexec" --oversubscribe -np 2 "$granshock" info >"$work/info" 2>&1
[ "$(grep -c '"processes": 2' "$work/info")" -eq 1 ] ||
  { echo "FAIL: info under mpirun -np 2"; cat "$work/info"; exit 1; }
echo "PASS"

#!/usr/bin/env bash
# Installs LAMMPS from Debian 12's own package `lammps` (20220106.git7586adbb6a+ds1-2:
# LAMMPS "29 Sep 2021 - Update 2" with the GRANULAR package, built against Open MPI), the
# reference the scripts in this folder were written and checked against. Nothing from
# outside Debian. Idempotent: does nothing when a LAMMPS binary is already on PATH.
#
# Debian installs the binary as `lmp`; upstream builds are often called lmp_serial or
# lmp_mpi, so common.sh's find_lmp accepts any of the three (or LMP=/path/to/binary).
# Run as root (or with sudo).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/common.sh"

if lmp=$(find_lmp 2>/dev/null); then
  echo "LAMMPS already installed: $lmp ($(lmp_version "$lmp"))"
  exit 0
fi
if [[ $(id -u) -ne 0 ]]; then
  echo "install_lammps.sh: needs root for apt-get (try: sudo $0)" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update
# lammps depends on libopenmpi3 and mpi-default-bin (Open MPI's mpirun).
apt-get install -y lammps
lmp=$(find_lmp)
echo "installed: $lmp ($(lmp_version "$lmp"))"
if ! lmp_has_granular "$lmp"; then
  echo "install_lammps.sh: $lmp lacks the GRANULAR package" >&2
  exit 1
fi

#!/usr/bin/env bash
# A refusal of `granshock fields --from-dump` (docs/fields.md, "Fields from LAMMPS or
# LIGGGHTS dumps"): one line matching PATTERN and exit code 2 (expect_user_error.sh), and
# nothing written: the --out directory must not exist afterwards.
# Usage: from_dump_refusal.sh PATTERN GRANSHOCK FORMAT MAP DUMP...
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
pattern=$1 granshock=$2 format=$3 map=$4
shift 4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$here/expect_user_error.sh" "$pattern" "$granshock" fields --from-dump "$format" "$@" \
  --map "$map" --out "$tmp/out" || exit 1
if [ -e "$tmp/out" ]; then
  echo "the refused command left $tmp/out behind:"
  ls -la "$tmp/out"
  exit 1
fi

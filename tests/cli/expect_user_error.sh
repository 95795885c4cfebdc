#!/usr/bin/env bash
# Runs a command that a user got wrong and checks how granshock answers it: exit code 2,
# nothing on stdout, exactly one line on stderr, which matches the expected pattern.
# Usage: expect_user_error.sh PATTERN COMMAND [ARGS...]
set -u
pattern=$1
shift
out=$(mktemp) err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
"$@" >"$out" 2>"$err"
code=$?
# Kokkos may warn about OpenMP thread binding on stderr; that is not granshock's answer.
grep -v -e '^Kokkos::OpenMP::initialize WARNING' -e '^  In general, for best' \
  -e '^  For best performance' -e '^  For unit testing' "$err" >"$err.own" || true
status=0
[ "$code" -eq 2 ] || { echo "expected exit code 2, got $code"; status=1; }
[ ! -s "$out" ] || { echo "expected no output on stdout, got:"; cat "$out"; status=1; }
lines=$(wc -l <"$err.own")
[ "$lines" -eq 1 ] || { echo "expected one line on stderr, got $lines:"; cat "$err.own"; status=1; }
grep -Eq -- "$pattern" "$err.own" || { echo "stderr does not match '$pattern':"; cat "$err.own"; status=1; }
rm -f "$err.own"
exit $status

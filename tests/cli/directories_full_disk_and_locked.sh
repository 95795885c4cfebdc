#!/usr/bin/env bash
# `granshock fields` and `granshock run` on a full disk and beside another granshock
# (docs/output_format.md, "The run directory" and "The fields directory"). A write that
# fails (a file-size limit, as on a full disk) ends with exit code 2 and one line on
# stderr, and leaves no temporary file; a claim that fails leaves no empty marker (a new
# directory stays unmarked, a marked one keeps its marker whole), so the same command
# works once there is room. A directory another granshock holds is refused, and so is an
# --out that granshock did not make.
# Usage: directories_full_disk_and_locked.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
fail() {
  echo "$*"
  status=1
}
# expect_error WHAT PATTERN: exit code $code, one line on stderr ($dir/err) matching PATTERN.
expect_error() {
  grep -v -e '^Kokkos::OpenMP::initialize WARNING' -e '^  ' "$dir/err" >"$dir/own" || true
  [ "$code" -eq 2 ] || fail "$1: expected exit code 2, got $code"
  [ "$(wc -l <"$dir/own")" -eq 1 ] || { fail "$1: expected one line on stderr:"; cat "$dir/own"; }
  grep -Eq -- "$2" "$dir/own" || { fail "$1: stderr does not match '$2':"; cat "$dir/own"; }
}
no_temporaries() {
  local left
  left=$(find "$1" -name '*.tmp')
  [ -z "$left" ] || fail "$2: temporaries left: $left"
}
# limited KIB ARGS...: granshock with a file-size limit; stderr through a pipe, whose
# writes the limit does not stop.
limited() {
  local kib=$1
  shift
  (
    ulimit -f "$kib"
    exec "$granshock" "$@" 2>&1 >/dev/null
  ) | cat >"$dir/err"
  code=${PIPESTATUS[0]}
}

short=(--quiet --set time.duration=0.004 --set time.production_start=0.002
  --set 'numerics.bin_size="6 d"' --set output.blocks=2)
"$granshock" run "$scene" --out "$dir/run" "${short[@]}" >/dev/null 2>"$dir/err" ||
  { cat "$dir/err"; exit 1; }
cp "$dir/run/.granshock-run" "$dir/marker"

# fields in place at several sizes: from the marker (0 KiB) to fields.h5 and the rest.
for kib in 0 1 16 64 256; do
  rm -rf "$dir/copy"
  cp -r "$dir/run" "$dir/copy"
  limited "$kib" fields "$dir/copy"
  expect_error "fields at $kib KiB" "(File too large|failed)"
  no_temporaries "$dir/copy" "fields at $kib KiB"
  [ -s "$dir/copy/.granshock-run" ] || fail "fields at $kib KiB: the marker was emptied"
done
# A new --out: no room even for the marker, then room.
limited 0 fields "$dir/run" --out "$dir/out"
expect_error "fields --out at 0 KiB" "granshock-fields.*File too large"
[ ! -e "$dir/out/.granshock-fields" ] || fail "fields --out at 0 KiB left a marker"
"$granshock" fields "$dir/run" --out "$dir/out" >/dev/null 2>"$dir/err" ||
  { fail "fields --out with room failed:"; cat "$dir/err"; }

# run: a new directory's claim, then a marked directory's, with no room at all.
limited 0 run "$scene" --out "$dir/fresh" --stop-after-steps 10 "${short[@]}"
expect_error "run at 0 KiB" "granshock-run.*File too large"
[ ! -e "$dir/fresh/.granshock-run" ] || fail "run at 0 KiB left a marker in a new directory"
"$granshock" run "$scene" --out "$dir/fresh" --stop-after-steps 10 "${short[@]}" \
  >/dev/null 2>"$dir/err" || { fail "run with room, after a full disk, failed:"; cat "$dir/err"; }
limited 0 run "$scene" --out "$dir/run" --overwrite "${short[@]}"
expect_error "run --overwrite at 0 KiB" "granshock-run.*File too large"
cmp -s "$dir/marker" "$dir/run/.granshock-run" ||
  fail "run --overwrite at 0 KiB changed the marker: $(cat "$dir/run/.granshock-run")"
[ -f "$dir/run/run.h5" ] || fail "run --overwrite at 0 KiB removed run.h5"

# Another granshock holds the directory (flock(1) stands for it).
if command -v flock >/dev/null; then
  flock "$dir/run/.granshock-run" "$granshock" fields "$dir/run" >/dev/null 2>"$dir/err"
  code=$?
  expect_error "fields into a locked run directory" "is in use by another granshock"
  flock "$dir/out/.granshock-fields" "$granshock" fields "$dir/run" --out "$dir/out" \
    >/dev/null 2>"$dir/err"
  code=$?
  expect_error "fields into a locked --out" "is in use by another granshock"
  flock "$dir/run/.granshock-run" "$granshock" fields "$dir/run" --out "$dir/out2" \
    >/dev/null 2>"$dir/err"
  code=$?
  expect_error "fields from a run directory being written" "in use by another granshock run"
  [ ! -e "$dir/out2" ] || fail "fields from a run directory being written created --out"
fi

# An --out granshock did not make (a home directory).
mkdir -p "$dir/home/figures"
echo mine >"$dir/home/figures/mach.png"
"$granshock" fields "$dir/run" --out "$dir/home" >/dev/null 2>"$dir/err"
code=$?
expect_error "fields --out a user's directory" "is not empty and was not written by granshock"
[ "$(cat "$dir/home/figures/mach.png")" = mine ] || fail "a user's figure was overwritten"
exit $status

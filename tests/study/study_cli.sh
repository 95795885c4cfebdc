#!/usr/bin/env bash
# `granshock study` end to end on tiny studies (tests/study/tiny.toml, interrupt.toml):
# one check per call, named by CHECK (docs/study.md describes what each one relies on).
# Usage: study_cli.sh GRANSHOCK SOURCE_DIR CHECK
#   runs_and_tabulates     every case runs; study.csv/json, detachment table and figures (the
#                          one check that draws every figure of a study: ctest runs the others
#                          with GRANSHOCK_FIGURES=0)
#   skips_finished         a finished case is skipped and its run files are left untouched
#   interrupts_and_resumes --stop-after-steps and SIGINT stop a case; the next call resumes it
#   collect_lists_missing  --collect tabulates what is there and lists the missing cases, and
#                          redraws the figures of a case it analyses again
#   emit_slurm             --emit slurm writes a script that bash accepts and that runs a case
#   refuses_before_running a bad late case or a foreign directory: one line, exit 2, no case run
#   set_reaches_every_case --set overrides every case after the file's [study] set, reaches the
#                          Slurm script, and a bad one is refused before any case runs
#   tradeoff_runs_and_tabulates  `granshock tradeoff`: the dry run, the 22 cases without
#                                figures, the table, the note's command drawing the figures
#                                (--collect), the table read by `granshock run --accuracy`
#   accuracy_per_case      --accuracy with a table: each case certified on its own scene (or
#                          not, outside the table's range, said in the dry run), recorded in
#                          its summary.json and study.csv, carried into the Slurm script
#   emit_slurm_hostile     hostile values (a newline and a command, $(...), quotes, '%', tab,
#                          CR) in the study directory, the study file's path and [study] set,
#                          --set and the program's path: the script runs case 1 and nothing else
#   emit_slurm_many_cases  more array tasks than Slurm's default MaxArraySize: one warning line
#   records_outlive_the_runs  each finished case's record (docs/study.md, "Campaign records"):
#                          its files and size; with the run directories removed, --collect
#                          tabulates every recorded case from its record and lists the rest
#                          as missing, and the study runs only the case without a record
#   summary_extremes       a case's summary.json with wall_seconds = 1e300 (the time limit is
#                          clamped), then nested 200 000 levels deep (one line, exit 2, for
#                          study --collect, --emit slurm, fields and run --accuracy-table)
set -u
granshock=$1 source=$2 check=$3
studies=$source/tests/study
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$work/out
status=0
fail() { echo "FAIL: $*"; status=1; }

# The data rows of study.csv whose status column is $1.
rows_with_status() { tail -n +2 "$out/study.csv" | grep -c ",\"$1\"," ; }
fingerprint() { for f in "$@"; do stat -c '%Y %s' "$f"; md5sum <"$f"; done; }

case $check in
runs_and_tabulates)
  start=$(date +%s%N)
  GRANSHOCK_FIGURES=1 "$granshock" study "$studies/tiny.toml" --out "$out" --quiet \
    >"$work/stdout" 2>"$work/stderr"
  code=$?
  echo "the tiny study (4 cases) took $((($(date +%s%N) - start) / 1000000)) ms"
  [ $code -eq 0 ] || { fail "exit code $code"; cat "$work/stderr"; }
  for k in 1 2 3 4; do
    grep -q "case $k/4 .*: finished in" "$work/stderr" || fail "no progress line after case $k/4"
  done
  grep -q "study ETA" "$work/stderr" || fail "no ETA in the progress lines"
  header=$(head -1 "$out/study.csv")
  case $header in
  case,index,status,source,wall_seconds,axis.phi,axis.e,scene.D_over_d,scene.U,scene.phi_inf,*) ;;
  *) fail "study.csv header: $header" ;;
  esac
  for column in scene.restitution scene.number_fraction.steel scene.duration \
    scene.production_start delta_over_D delta_over_D_reason ma_inf_measured phi_peak steps \
    inflow.requested; do
    echo "$header" | tr ',' '\n' | grep -qx "$column" || fail "study.csv has no column $column"
  done
  [ "$(rows_with_status finished)" -eq 4 ] || fail "expected 4 finished rows:"$'\n'"$(cat "$out/study.csv")"
  grep -q '^"phi-0.12_e-0.8",3,"finished",' "$out/study.csv" || fail "no row for case 3"
  python3 - "$out/study.json" <<'EOF' || fail "study.json"
import json, sys
rows = json.load(open(sys.argv[1]))
assert len(rows) == 4, len(rows)
assert [r["case"] for r in rows] == ["phi-0.1_e-0.5", "phi-0.1_e-0.8", "phi-0.12_e-0.5", "phi-0.12_e-0.8"]
assert rows[2]["axis.phi"] == 0.12 and rows[2]["axis.e"] == 0.5, rows[2]
assert all(r["steps"] == 20000 and r["completed"] is True for r in rows)
assert all(len(r) == len(rows[0]) for r in rows)
EOF
  [ "$(($(wc -l <"$out/detachment.csv") - 1))" -eq 4 ] || fail "detachment.csv should have 4 rows"
  if /usr/bin/python3 -c "import matplotlib, h5py, numpy" 2>/dev/null; then
    for png in phi e detachment_length phi-0.1_e-0.5/figures/mach.png phi-0.12_e-0.8/figures/mach.png; do
      png=${png%.png}.png
      [ -s "$out/figures/$png" ] || [ -s "$out/$png" ] || fail "no figure $png"
    done
  else
    grep -q "no axis figures" "$work/stderr" || fail "no warning about the missing figures"
  fi
  ;;
skips_finished)
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet --case 0 2>"$work/stderr" ||
    fail "--case 0 failed: $(cat "$work/stderr")"
  [ ! -e "$out/study.csv" ] || fail "--case must not build the table"
  [ ! -e "$out/phi-0.1_e-0.8" ] || fail "--case 0 ran another case"
  case0=$out/phi-0.1_e-0.5
  before=$(fingerprint "$case0/run.h5" "$case0/checkpoint.h5")
  summary=$(cat "$case0/summary.json")
  sleep 1.1  # a rewrite would change the modification time
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet 2>"$work/stderr" ||
    fail "the study failed: $(cat "$work/stderr")"
  grep -q "case 1/4 phi-0.1_e-0.5: finished before, skipped" "$work/stderr" ||
    fail "case 0 was not skipped: $(cat "$work/stderr")"
  grep -q "case 1/4 .*starting" "$work/stderr" && fail "case 0 was run again"
  [ "$before" = "$(fingerprint "$case0/run.h5" "$case0/checkpoint.h5")" ] ||
    fail "the skipped case's run.h5 or checkpoint.h5 changed"
  [ "$summary" = "$(cat "$case0/summary.json")" ] || fail "the skipped case's summary.json changed"
  [ "$(rows_with_status finished)" -eq 4 ] || fail "expected 4 finished rows"
  ;;
interrupts_and_resumes)
  study=$studies/interrupt.toml
  case0=$out/e-0.5
  "$granshock" study "$study" --out "$out" --quiet --stop-after-steps 5000 2>"$work/stderr"
  code=$?
  [ $code -eq 0 ] || fail "--stop-after-steps: exit code $code"
  grep -q "stopped in case 1/2 e-0.5 at step 5000 of 1000000" "$work/stderr" ||
    fail "no stop message: $(cat "$work/stderr")"
  grep -q '"completed": false' "$case0/summary.json" || fail "case 0 should be unfinished"
  [ ! -e "$out/e-0.8" ] || fail "the study went on after a stopped case"
  [ ! -e "$out/study.csv" ] || fail "a stopped study must not build the table"

  "$granshock" study "$study" --out "$out" --quiet 2>"$work/stderr" &
  pid=$!
  for _ in $(seq 100); do grep -q "resuming at step 5000" "$work/stderr" && break; sleep 0.1; done
  sleep 0.5
  kill -INT $pid
  wait $pid
  code=$?
  [ $code -eq 130 ] || fail "SIGINT: exit code $code, expected 130: $(cat "$work/stderr")"
  grep -q "resuming at step 5000 of 1000000" "$work/stderr" || fail "case 0 was not resumed"
  grep -Eq "interrupted (in|before) case" "$work/stderr" || fail "no interruption message"

  "$granshock" study "$study" --out "$out" --quiet 2>"$work/stderr"
  code=$?
  [ $code -eq 0 ] || fail "the third call: exit code $code: $(cat "$work/stderr")"
  for dir in "$out/e-0.5" "$out/e-0.8"; do
    grep -q '"completed": true' "$dir/summary.json" || fail "$dir did not complete"
    grep -q '"steps": 1000000' "$dir/summary.json" || fail "$dir did not run all 1000000 steps"
  done
  [ "$(rows_with_status finished)" -eq 2 ] || fail "expected 2 finished rows"
  ;;
records_outlive_the_runs)
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet 2>"$work/stderr" ||
    fail "the study failed: $(cat "$work/stderr")"
  records=$out/records
  for name in phi-0.1_e-0.5 phi-0.1_e-0.8 phi-0.12_e-0.5 phi-0.12_e-0.8; do
    for f in summary.json scene.toml fields.h5 record.json; do
      [ -s "$records/cases/$name/$f" ] || fail "no record file $name/$f"
    done
    bytes=$(du -cb "$records/cases/$name"/* | tail -1 | cut -f1)
    [ "$bytes" -lt 1000000 ] || fail "the record of $name is $bytes bytes, past 1 MB"
  done
  [ -s "$records/study.csv" ] || fail "no study.csv beside the records"
  # The record's fields: the run's own, as float32 (to float32's rounding), the grid and the
  # profile kept; the summary the run's byte for byte; the scene the resolved one.
  /usr/bin/python3 - "$out/phi-0.1_e-0.8" "$records/cases/phi-0.1_e-0.8" <<'EOF' || fail "the record does not hold the run's fields"
import json, sys
import h5py, numpy as np
run, rec = sys.argv[1:]
with h5py.File(run + "/fields.h5") as a, h5py.File(rec + "/fields.h5") as b:
    assert b.attrs["granshock_record"] == 1 and b.attrs["granshock_file"] == a.attrs["granshock_file"]
    for q in ["phi", "T", "Ma", "mean_count"]:
        x, y = a["fields/" + q][...], b["fields/" + q][...]
        assert y.dtype == np.float32 and y.shape == x.shape, (q, y.dtype, y.shape)
        ok = np.isfinite(x)
        assert np.array_equal(ok, np.isfinite(y)), q
        assert np.all(np.abs(y[ok] - x[ok]) <= 1e-6 * np.abs(x[ok]) + 1e-30), q
    assert np.array_equal(a["fields/masked"][...] != 0, b["fields/masked"][...] != 0)
    assert np.array_equal(a["grid/x"][...], b["grid/x"][...])
    assert np.array_equal(a["profile/phi"][...], b["profile/phi"][...], equal_nan=True)
    assert "vectors" not in b and "nodes" not in b["grid"]
# The summary the run's, with no path of this machine: the run directory's named by the case.
import os
text = open(run + "/summary.json").read().replace(os.path.abspath(run), "phi-0.1_e-0.8")
assert json.loads(text) == json.load(open(rec + "/summary.json"))
assert os.path.dirname(os.path.abspath(run)) not in open(rec + "/summary.json").read()
origin = json.load(open(rec + "/record.json"))
assert origin["record"] == "granshock case record 1" and origin["case"] == "phi-0.1_e-0.8", origin
# The study file was named by its absolute path here: the record keeps its name alone.
assert origin["command"] in ("granshock study tiny.toml --case 1", "granshock study 'tiny.toml' --case 1"), origin
assert origin["cpu_model"], origin
assert origin["study_file"] == "tiny.toml", origin
EOF
  grep -Eq "^name = [\"']phi-0.1_e-0.8[\"']" "$records/cases/phi-0.1_e-0.8/scene.toml" ||
    fail "the record's scene is not the case's resolved scene"
  # --collect with nothing new leaves every record as it was (a committed record changes
  # only when its numbers or settings do; HDF5 files are not written byte for byte alike).
  before=$(fingerprint "$records"/cases/*/fields.h5 "$records"/cases/*/summary.json)
  sleep 1.1
  "$granshock" study "$studies/tiny.toml" --out "$out" --collect --quiet 2>"$work/stderr" >/dev/null ||
    fail "--collect failed: $(cat "$work/stderr")"
  [ "$before" = "$(fingerprint "$records"/cases/*/fields.h5 "$records"/cases/*/summary.json)" ] ||
    fail "--collect rewrote records whose numbers had not changed"
  # The run directories gone: every case from its record.
  rm -r "${out:?}"/phi-*
  "$granshock" study "$studies/tiny.toml" --out "$out" --collect 2>"$work/stderr" >/dev/null ||
    fail "--collect from records failed: $(cat "$work/stderr")"
  [ "$(rows_with_status finished)" -eq 4 ] || fail "expected 4 finished rows from the records"
  [ "$(grep -c '"finished","record",' "$out/study.csv")" -eq 4 ] ||
    fail "the rows do not say they come from the records: $(cut -c1-80 "$out/study.csv")"
  grep -q "4 cases from $records alone" "$work/stderr" || fail "no note of the records: $(cat "$work/stderr")"
  head -1 "$out/study.csv" | tr ',' '\n' | grep -qx delta_over_D || fail "no summary columns"
  # One record gone too: listed as missing, and the only case a run runs again.
  rm -r "${records:?}/cases/phi-0.12_e-0.5"
  "$granshock" study "$studies/tiny.toml" --out "$out" --collect 2>"$work/stderr" >/dev/null
  [ $? -eq 1 ] || fail "--collect with a case missing: exit code, expected 1"
  grep -q "1 of 4 cases not finished: phi-0.12_e-0.5 (missing)" "$work/stderr" ||
    fail "the missing case is not listed: $(cat "$work/stderr")"
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet 2>"$work/stderr" ||
    fail "the study failed: $(cat "$work/stderr")"
  [ "$(grep -c 'finished before (its record in' "$work/stderr")" -eq 3 ] ||
    fail "the recorded cases were not skipped: $(cat "$work/stderr")"
  [ -d "$out/phi-0.12_e-0.5" ] && [ ! -e "$out/phi-0.1_e-0.5" ] || fail "the wrong cases ran"
  [ -s "$records/cases/phi-0.12_e-0.5/summary.json" ] || fail "the case run again has no record"
  # A record of other settings under the same name is not the case's: it runs again, and
  # its record is replaced.
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet --case 0 \
    --set output.series_interval=0.001 2>"$work/stderr" || fail "--case 0 failed: $(cat "$work/stderr")"
  grep -q "phi-0.1_e-0.5: its record in .* was made with other settings" "$work/stderr" ||
    fail "a record of other settings was used: $(cat "$work/stderr")"
  [ -s "$out/phi-0.1_e-0.5/summary.json" ] || fail "the case of other settings did not run"
  grep -q "output.series_interval=0.001" "$records/cases/phi-0.1_e-0.5/record.json" ||
    fail "its record was not replaced"
  # A fresh clone: the study's directory gone altogether, its records kept elsewhere
  # ([study] records): --collect makes the directory and the table from the records.
  cp -r "$records" "$work/kept"
  sed -e "s|^base = .*|base = \"$source/scenes/default.toml\"|" \
    -e "s|^name = \"tiny\"|name = \"tiny\"\nrecords = \"$work/kept\"|" "$studies/tiny.toml" >"$work/kept.toml"
  "$granshock" study "$work/kept.toml" --out "$work/fresh" --collect --no-figures 2>"$work/stderr" >/dev/null
  [ $? -eq 1 ] || fail "--collect on a fresh clone: exit code (case 0's record is of other settings)"
  [ "$(grep -c '"finished","record",' "$work/fresh/study.csv")" -eq 3 ] ||
    fail "a fresh clone's --collect did not tabulate the records: $(cat "$work/stderr")"
  grep -q "1 of 4 cases not finished: phi-0.1_e-0.5 (missing)" "$work/stderr" ||
    fail "the case of other settings is not listed as missing: $(cat "$work/stderr")"
  ;;
collect_lists_missing)
  "$granshock" study "$studies/tiny.toml" --out "$out" --collect 2>"$work/stderr"
  [ $? -eq 2 ] || fail "--collect without a study directory must be a user error"
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet --case 2 2>"$work/stderr" ||
    fail "--case 2 failed: $(cat "$work/stderr")"
  # --no-figures where the environment asks for figures: none drawn, and the study's own
  # closing note (which --quiet keeps) names the --collect that draws them.
  GRANSHOCK_FIGURES=1 "$granshock" study "$studies/tiny.toml" --out "$out" --collect --quiet \
    --no-figures >"$work/stdout" 2>"$work/stderr"
  code=$?
  [ $code -eq 1 ] || fail "--collect with missing cases: exit code $code, expected 1"
  [ "$(grep 'figures not drawn' "$work/stderr")" = "granshock: figures not drawn (--no-figures); draw them later with: granshock study $studies/tiny.toml --out $out --collect" ] ||
    fail "--collect --no-figures: the closing note: $(grep 'not drawn' "$work/stderr")"
  grep -q "3 of 4 cases not finished: phi-0.1_e-0.5 (missing), phi-0.1_e-0.8 (missing), phi-0.12_e-0.8 (missing)" \
    "$work/stderr" || fail "the missing cases are not listed: $(cat "$work/stderr")"
  [ "$(tail -n +2 "$out/study.csv" | wc -l)" -eq 4 ] || fail "study.csv should have 4 rows"
  [ "$(rows_with_status missing)" -eq 3 ] || fail "expected 3 missing rows"
  grep -q '^"phi-0.12_e-0.5",2,"finished",' "$out/study.csv" || fail "case 2 is not finished"
  head -1 "$out/study.csv" | tr ',' '\n' | grep -qx delta_over_D || fail "no summary columns"
  [ ! -e "$out/phi-0.1_e-0.5" ] || fail "--collect ran a case"
  # Neither the run (GRANSHOCK_FIGURES=0, ctest's environment) nor --collect --no-figures
  # drew a figure.
  [ ! -e "$out/phi-0.12_e-0.5/figures" ] && [ ! -e "$out/figures" ] ||
    fail "figures drawn without figures: $(ls "$out/figures" "$out/phi-0.12_e-0.5/figures" 2>&1)"
  # A case analysed by an older granshock (its summary.json without the keys of today's
  # analysis) is analysed again before it is tabulated, and its figures drawn from the new
  # analysis (old ones would show the old fronts).
  /usr/bin/python3 -c 'import json, sys; p = sys.argv[1]; s = json.load(open(p)); s.pop("detachment"); json.dump(s, open(p, "w"))' \
    "$out/phi-0.12_e-0.5/summary.json"
  GRANSHOCK_FIGURES=1 "$granshock" study "$studies/tiny.toml" --out "$out" --collect --quiet \
    >/dev/null 2>&1
  head -1 "$out/study.csv" | tr ',' '\n' | grep -qx detachment.temperature_jump.delta_over_D ||
    fail "the table holds the stale summary: $(head -1 "$out/study.csv")"
  if /usr/bin/python3 -c "import matplotlib, h5py, numpy" 2>/dev/null; then
    for png in solid_fraction temperature mach stagnation_profiles; do
      [ -s "$out/phi-0.12_e-0.5/figures/$png.png" ] ||
        fail "--collect analysed the case again but did not draw figures/$png.png"
    done
  fi
  ;;
emit_slurm)
  "$granshock" study "$studies/tiny.toml" --out "$out" --emit slurm >"$work/stdout" 2>"$work/stderr" ||
    fail "--emit slurm failed: $(cat "$work/stderr")"
  script=$out/study.slurm
  [ -s "$script" ] || fail "no $script"
  bash -n "$script" || fail "bash -n refuses the script"
  grep -qx '#SBATCH --array=0-3' "$script" || fail "array range"
  grep -qx '#SBATCH --cpus-per-task=4' "$script" || fail "cpus per task"
  grep -Eqx '#SBATCH --time=[0-9]+-[0-9]{2}:[0-9]{2}:00' "$script" || fail "time limit"
  grep -q 'OMP_NUM_THREADS="${SLURM_CPUS_PER_TASK' "$script" || fail "threads"
  grep -Fqx "exec '$granshock' study '$studies/tiny.toml' --out '$out' --case \"\$((10#\$SLURM_ARRAY_TASK_ID + 10#\$first_case))\"" \
    "$script" || fail "the command line: $(grep '^exec' "$script")"
  ls "$out" | grep -qv '^study.slurm$' && fail "--emit ran something: $(ls "$out")"
  # The script itself, as an array task of a job would run it.
  (cd "$work" && SLURM_ARRAY_TASK_ID=1 SLURM_CPUS_PER_TASK=1 bash "$script" >/dev/null 2>&1) ||
    fail "the script failed as array task 1"
  grep -q '"completed": true' "$out/phi-0.1_e-0.8/summary.json" 2>/dev/null ||
    fail "array task 1 did not run case 1"
  [ ! -e "$out/phi-0.1_e-0.5" ] || fail "array task 1 ran case 0 as well"
  ;;
set_reaches_every_case)
  # The tiny study's 4 ms shortened to 3 ms: case 2 alone, 15 000 steps of 2e-7 s.
  "$granshock" study "$studies/tiny.toml" --out "$out" --case 2 --quiet \
    --set time.duration=0.003 >"$work/stdout" 2>"$work/stderr" || fail "--set: $(cat "$work/stderr")"
  grep -q '"steps": 15000' "$out/phi-0.12_e-0.5/summary.json" 2>/dev/null ||
    fail "case 2 did not run 3 ms: $(grep '"steps"' "$out/phi-0.12_e-0.5/summary.json")"
  "$granshock" study "$studies/tiny.toml" --out "$work/slurm" --emit slurm \
    --set 'time.duration=0.003' >/dev/null 2>&1 || fail "--emit slurm with --set"
  grep -q -- "--set 'time.duration=0.003' --case" "$work/slurm/study.slurm" ||
    fail "the script drops --set: $(grep '^exec' "$work/slurm/study.slurm")"
  bash -n "$work/slurm/study.slurm" || fail "bash -n refuses the script"
  "$granshock" study "$studies/tiny.toml" --out "$work/bad" --set nosuch.key=1 2>"$work/stderr"
  code=$?
  [ $code -eq 2 ] || fail "a bad --set: exit code $code"
  grep -q "nosuch" "$work/stderr" || fail "the refusal does not name the key: $(cat "$work/stderr")"
  [ ! -e "$work/bad/phi-0.1_e-0.5" ] || fail "a case ran despite the bad --set"
  ;;
refuses_before_running)
  "$granshock" study "$studies/bad/late_bad_value.toml" --out "$out" 2>"$work/stderr"
  code=$?
  [ $code -eq 2 ] || fail "a bad fourth case: exit code $code"
  [ "$(grep -vc '^Kokkos::' "$work/stderr")" -eq 1 ] || fail "expected one line: $(cat "$work/stderr")"
  grep -q "case 'phi-0.69' (--case 3): scene key 'inflow.area_fraction'" "$work/stderr" ||
    fail "the message: $(cat "$work/stderr")"
  [ ! -e "$out" ] || fail "a refused study created its directory"
  mkdir -p "$work/mine" && echo notes >"$work/mine/notes.txt"
  "$granshock" study "$studies/tiny.toml" --out "$work/mine" 2>"$work/stderr"
  [ $? -eq 2 ] || fail "a foreign directory must be refused"
  grep -q "is not empty and holds no study" "$work/stderr" || fail "the message: $(cat "$work/stderr")"
  [ "$(ls "$work/mine")" = notes.txt ] || fail "the foreign directory was changed"
  "$granshock" study "$studies/tiny.toml" --out "$out" --emit slurm >/dev/null 2>&1
  "$granshock" study "$studies/interrupt.toml" --out "$out" --dry-run 2>"$work/stderr" >/dev/null
  [ $? -eq 2 ] || fail "another study's directory must be refused"
  grep -q "holds the study 'tiny', not 'interrupt'" "$work/stderr" || fail "the message: $(cat "$work/stderr")"
  ;;
tradeoff_runs_and_tabulates)
  # `granshock tradeoff` on the default scene shrunk as tiny.toml shrinks it, 2 ms simulated
  # (docs/accuracy.md):
  # a dry run writes nothing; the run makes 22 cases, the study file and the trade table.
  # Without figures (GRANSHOCK_FIGURES=0 from ctest), then drawn by the command the closing
  # note names, as a user would (a `granshock` on PATH).
  tiny=(--set "domain.width=40 d" --set "domain.length=60 d" --set "obstacle.diameter=10 d"
    --set 'obstacle.centre=["20 d", "35 d"]' --set time.duration=0.002
    --set time.production_start=0.001 --set output.sample_every=20
    --set output.snapshot_interval=0.002 --set output.checkpoint_interval=0.001
    --set output.series_interval=0.0005 --set output.progress_interval=1000)
  "$granshock" tradeoff "$source/scenes/default.toml" --out "$out" --dry-run "${tiny[@]}" \
    >"$work/stdout" 2>"$work/stderr" || fail "--dry-run failed: $(cat "$work/stderr")"
  grep -q -- "--case 21  reference-seed-2" "$work/stdout" ||
    fail "the dry run lists no 22nd case: $(cat "$work/stdout")"
  [ ! -e "$out" ] || fail "--dry-run wrote $out"
  GRANSHOCK_FIGURES=0 "$granshock" tradeoff "$source/scenes/default.toml" --out "$out" --quiet "${tiny[@]}" \
    >"$work/stdout" 2>"$work/stderr" || fail "the trade-off failed: $(tail -5 "$work/stderr")"
  [ -s "$out/tradeoff.toml" ] || fail "no tradeoff.toml"
  [ "$(tail -n +2 "$out/trade.csv" | wc -l)" -eq 22 ] || fail "trade.csv should have 22 rows"
  for f in trade.md trade.json; do [ -s "$out/$f" ] || fail "no $f"; done
  [ ! -e "$out/pareto.png" ] && [ ! -e "$out/reference/figures" ] || fail "figures drawn without figures"
  note=$(grep '^granshock: figures not drawn (GRANSHOCK_FIGURES=0); draw them later with: GRANSHOCK_FIGURES=1 granshock tradeoff ' "$work/stderr")
  [ "$(printf '%s' "$note" | grep -c .)" -eq 1 ] || fail "expected one closing note: $(grep 'not drawn' "$work/stderr")"
  if /usr/bin/python3 -c "import matplotlib, h5py, numpy" 2>/dev/null; then
    mkdir "$work/bin" && ln -s "$(realpath "$granshock")" "$work/bin/granshock"
    (PATH=$work/bin:$PATH && eval "${note#*draw them later with: }") >"$work/redraw" 2>&1 ||
      fail "the note's command failed: ${note#*with: }: $(tail -5 "$work/redraw")"
    for f in pareto.png reference/figures/mach.png seed-2/figures/stagnation_profiles.png; do
      [ -s "$out/$f" ] || fail "the note's command did not draw $f"
    done
    # --collect --no-figures where the environment asks for figures: none drawn again.
    rm -r "$out/pareto.png" "$out/reference/figures"
    GRANSHOCK_FIGURES=1 "$granshock" tradeoff "$source/scenes/default.toml" --out "$out" \
      --quiet --collect --no-figures "${tiny[@]}" >"$work/stdout" 2>"$work/stderr" ||
      fail "tradeoff --collect --no-figures failed: $(tail -5 "$work/stderr")"
    [ ! -e "$out/pareto.png" ] && [ ! -e "$out/reference/figures" ] ||
      fail "tradeoff --no-figures drew figures"
    grep -q '^granshock: figures not drawn (--no-figures); draw them later with: granshock tradeoff .* --collect$' \
      "$work/stderr" || fail "tradeoff --no-figures: the closing note: $(cat "$work/stderr")"
  fi
  /usr/bin/python3 -c '
import json, os, sys
t = json.load(open(sys.argv[1]))
ref = t["cases"][0]
assert ref["case"] == "reference" and ref["speedup"] == 1.0, ref
assert abs(ref["dt_over_tc"] - 0.01) < 1e-6, ref["dt_over_tc"]
# The speed-ups are CPU times (summary.json cpu_seconds), not wall times (docs/accuracy.md).
assert all(c["cost_from"] == "cpu_seconds" and c["cpu_seconds"] > 0 for c in t["cases"]), t["cases"]
assert "| CPU (s) |" in open(os.path.join(os.path.dirname(sys.argv[1]), "trade.md")).read()
soft = [c for c in t["cases"] if c["case"] == "soft-1000"][0]
assert soft["speedup"] > 1, soft["speedup"]
assert t["noise"]["L2.phi"] > 0, t["noise"]
# The settings --accuracy chooses from, read from the resolved scene of each case.
assert soft["softening"] == 1000.0 and soft["changed"] == "contact.softening time.dt", soft
single = [c for c in t["cases"] if c["case"] == "single"][0]
assert single["precision"] == "single" and single["changed"] == "numerics.precision", single
assert [c for c in t["cases"] if c["case"] == "scene"][0]["changed"] == ""
# Where the table holds: its own scene (D = 10 d here, Ma 5.9), named.
r = t["certified_range"]
assert all(abs(v - 10) < 1e-9 for v in r["D_over_d"]) and r["mach"] == [5.9, 5.9], r
assert r["shown_on"] == ["default"], r
# e_eff averaged over the phase of the first contact step (judged by --accuracy) beside
# the one-phase value, both from the summary.json of each case.
for c in t["cases"]:
    assert 0 <= c["e_eff_error_phase_averaged"] < 1 and 0 <= c["e_eff_error"] < 1, c
# The noise: the RMS over the 6 pairs of the 4 seeds of the scene as given, recomputed here
# from their summary.json; for delta/D at least the combined block errors of two runs (the
# seeds can agree by chance). The certificate: one-sided 90 %, t at 3 degrees of freedom.
import itertools, math, os
seeds = ["scene", "seed-2", "seed-3", "seed-4"]
assert t["noise_from"].startswith("the scene") and "4 seeds" in t["noise_from"], t["noise_from"]
assert "6 pairs" in t["noise_from"], t["noise_from"]
assert t["table"] == "granshock trade table 2" and t["noise_seeds"] == 4, t["table"]
assert t["certificate"]["k"] == 1.638 and t["certificate"]["confidence"] == 0.9, t["certificate"]
assert t["noise_floor"]["bound"] > 0 and t["noise_floor"]["by"], t["noise_floor"]
runs = {n: json.load(open(os.path.join(os.path.dirname(sys.argv[1]), n, "summary.json")))
        for n in seeds}
pairs = list(itertools.combinations(seeds, 2))
phi = [abs(runs[a]["phi_peak"] - runs[b]["phi_peak"]) for a, b in pairs]
rms = math.sqrt(sum(x * x for x in phi) / len(phi))
assert abs(t["noise"]["phi_peak"] - rms) <= 1e-12 * max(rms, 1e-300), (t["noise"]["phi_peak"], rms)
errs = [runs[n]["detachment"]["temperature_jump"]["delta_over_D_err"] for n in seeds]
if None not in errs:
    floor = math.sqrt(2 * sum(e * e for e in errs) / len(errs))
    assert t["noise"]["delta_over_D.temperature_jump"] >= floor - 1e-15, (t["noise"], errs)
# The discrete mode with each softening, measured.
for f in ("10", "100", "1000"):
    c = [c for c in t["cases"] if c["case"] == f"soft-{f}-discrete"][0]
    assert c["restitution_mode"] == "discrete" and c["softening"] == float(f), c
    assert c["changed"] == "contact.restitution_mode contact.softening time.dt", c
' "$out/trade.json" || fail "trade.json: the reference, the speed-up, the noise or a setting is wrong"
  # The table from the records alone (docs/study.md, "Campaign records"): the run
  # directories removed, trade_table.py makes the same table.
  mv "$out/trade.json" "$work/trade_from_runs.json"
  rm -r "${out:?}/reference" "${out:?}/scene" "${out:?}/soft-1000"
  /usr/bin/python3 "$source/cases/tradeoff/trade_table.py" "$out/records" "$work/again" --no-figures \
    >/dev/null || fail "trade_table.py on the records failed"
  /usr/bin/python3 -c '
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
a.pop("certified_range")
b.pop("certified_range", None)
assert a == b, "the table from the records differs from the one from the runs"
' "$work/trade_from_runs.json" "$work/again/trade.json" || fail "the records give another table"
  mv "$work/trade_from_runs.json" "$out/trade.json"
  # The table feeds --accuracy: a budget the table cannot certify runs the scene as given
  # (its own dt, not the reference's t_c/100), and says so with the seeds of the noise.
  "$granshock" run "$source/scenes/default.toml" "${tiny[@]}" --accuracy 0.001% \
    --accuracy-table "$out/trade.json" --dry-run --out "$work/never" >"$work/choice" 2>&1 ||
    fail "--accuracy with the table failed: $(cat "$work/choice")"
  grep -q '# accuracy: cannot certify: no measured setting is within 0.001 %.*noise from 4 seeds' "$work/choice" ||
    fail "--accuracy did not say that nothing met the budget: $(cat "$work/choice")"
  grep -q '# accuracy: so: nothing changed, the scene as given' "$work/choice" ||
    fail "--accuracy did not run the scene as given: $(cat "$work/choice")"
  grep -q '^dt = 2e-07$' "$work/choice" || grep -q '^dt = 2.0e-07$' "$work/choice" ||
    grep -Eq '^dt = 2(\.0*)?e-0?7' "$work/choice" ||
    fail "the scene's own dt is not the resolved one: $(grep '^dt' "$work/choice")"
  # The certified bound trade_table.py writes for each case is the one --accuracy computes
  # (cases/accuracy/accuracy_table.cpp): a budget every case meets chooses the fastest, and
  # names its bound.
  "$granshock" run "$source/scenes/default.toml" "${tiny[@]}" --accuracy 100000% \
    --accuracy-table "$out/trade.json" --dry-run --out "$work/never" >"$work/choice" 2>&1 ||
    fail "--accuracy 100000% failed: $(cat "$work/choice")"
  /usr/bin/python3 - "$out/trade.json" "$work/choice" <<'EOF' || fail "trade.json's bound is not the one --accuracy computes"
import json, re, sys
table = json.load(open(sys.argv[1]))
line = next(l for l in open(sys.argv[2]) if l.startswith("# accuracy: chose "))
name, bound = re.match(r'# accuracy: chose "([^"]+)" .*?error at most ([0-9.e+-]+) %', line).groups()
row = next(c for c in table["cases"] if c["case"] == name)
assert abs(100 * row["bound"] - float(bound)) <= 0.006 * float(bound), (row["bound"], bound, line)
EOF
  # A transfer check (cases/tradeoff/transfer_table.py) with the same records as the other
  # scene: every bound as the table's own, the range named twice, and --accuracy reads it.
  /usr/bin/python3 "$source/cases/tradeoff/transfer_table.py" "$out/records" "$work/combined" \
    "$out/records" --no-figures >/dev/null || fail "transfer_table.py failed"
  /usr/bin/python3 - "$out/trade.json" "$work/combined/trade.json" <<'EOF' || fail "the transfer table is wrong"
import json, sys
own, combined = (json.load(open(p)) for p in sys.argv[1:])
assert len(combined["transfers"]) == 1 and combined["transfers"][0]["shown_on"] == "out"
assert combined["certified_range"]["shown_on"] == ["out", "out"], combined["certified_range"]
for a, b in zip(own["cases"], combined["cases"]):
    assert a["case"] == b["case"] and a["bound"] == b["bound"], (a["case"], a["bound"], b["bound"])
    assert set(b["bound_on"]) == {"out"}, b["bound_on"]
EOF
  "$granshock" run "$source/scenes/default.toml" "${tiny[@]}" --accuracy 100000% \
    --accuracy-table "$work/combined/trade.json" --dry-run --out "$work/never" >"$work/choice2" 2>&1 ||
    fail "--accuracy with the transfer table failed: $(cat "$work/choice2")"
  [ "$(grep '^# accuracy: chose ' "$work/choice")" = "$(grep '^# accuracy: chose ' "$work/choice2")" ] ||
    fail "the transfer table chose otherwise: $(grep 'chose' "$work/choice2")"
  ;;
accuracy_per_case)
  # The default scene's table (docs/results/tradeoff/default: shown on D = 20 d, Ma 5.9) and
  # the tiny study at D = 10 d: not certified; at D = 20 d: certified, every case its own dt.
  table=$source/docs/results/tradeoff/default/trade.json
  "$granshock" study "$studies/tiny.toml" --out "$out" --accuracy 20% --accuracy-table "$table" \
    --dry-run >"$work/stdout" 2>"$work/stderr" || fail "--dry-run failed: $(cat "$work/stderr")"
  [ "$(grep -c 'accuracy 20 %: not certified, the scene as given' "$work/stdout")" -eq 4 ] ||
    fail "D = 10 d should not be certified by a table shown on D = 20 d: $(cat "$work/stdout")"
  wide=(--set "obstacle.diameter=20 d")
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet --accuracy 20% \
    --accuracy-table "$table" "${wide[@]}" >"$work/stdout" 2>"$work/stderr" ||
    fail "the study failed: $(cat "$work/stderr")"
  python3 - "$out" <<'EOF' || fail "the chosen settings are not where they belong"
import json, os, sys
out = sys.argv[1]
rows = json.load(open(os.path.join(out, "study.json")))
assert len(rows) == 4, len(rows)
for r in rows:
    assert r["status"] == "finished", r["status"]
    assert r["accuracy.case"] == "soft-100" and r["accuracy.certified"] is True, r
    s = json.load(open(os.path.join(out, r["case"], "summary.json")))
    choice = s["accuracy_choice"]
    assert choice["case"] == "soft-100" and choice["certified"] is True, choice
    assert abs(choice["scene_D_over_d"] - 20) < 1e-9, choice
    assert r["scene.dt"] == choice["dt"], (r["scene.dt"], choice["dt"])
# Each case's own t_c: restitution and phi move it a little, so every dt differs.
assert len({r["scene.dt"] for r in rows}) == 4, [r["scene.dt"] for r in rows]
EOF
  header=$(head -1 "$out/study.csv")
  for column in accuracy.case accuracy.certified accuracy.dt_over_tc accuracy.softening; do
    echo "$header" | tr ',' '\n' | grep -qx "$column" || fail "study.csv has no column $column"
  done
  "$granshock" study "$studies/tiny.toml" --out "$out" --accuracy 20% --accuracy-table "$table" \
    "${wide[@]}" --emit slurm >/dev/null 2>"$work/stderr" || fail "--emit slurm: $(cat "$work/stderr")"
  grep -q -- "--accuracy '20%' --accuracy-table '$table' --case " "$out/study.slurm" ||
    fail "the Slurm tasks do not choose as the plan did: $(grep exec "$out/study.slurm")"
  ;;
emit_slurm_hostile)
  hostile=$'x\ntouch PWNED #$(touch PWNED)`touch PWNED`\'"%A\t\r end'
  mkdir -p "$work/bin$hostile" "$work/study$hostile" "$work/cwd" "$work/task"
  cp "$granshock" "$work/bin$hostile/granshock"
  study=$work/study$hostile/tiny.toml
  # tiny.toml with the study directory in `out` and a [study] set value that hold a newline
  # and a command (TOML escapes); the override is still valid TOML (v = 0.004, touch = "PWNED").
  {
    echo '[study]'
    echo 'name = "tiny"'
    echo "base = \"$source/scenes/default.toml\""
    echo 'out = "outx\ntouch PWNED #$(touch PWNED)`touch PWNED`'"'"'\"%A\t\r end"'
    sed -n '/^set = \[/,/\]$/p' "$studies/tiny.toml" | sed 's/^set = \[/set = ["time.duration=0.004\\ntouch = \\"PWNED\\"", /'
    sed -n '/^\[\[axis\]\]/,$p' "$studies/tiny.toml"
  } >"$study"
  set_value=$'time.duration=0.003\t# $(touch PWNED) `touch PWNED` \'q\' "dq" %A\r\ntouch = "PWNED"'
  (cd "$work/cwd" && "$work/bin$hostile/granshock" study "$study" --emit slurm --set "$set_value") \
    >"$work/stdout" 2>"$work/stderr" || fail "--emit slurm failed: $(cat "$work/stderr")"
  dir=$work/cwd/out$hostile
  script=$dir/study.slurm
  [ -s "$script" ] || fail "no study.slurm in the hostile study directory: $(ls -R "$work/cwd")"
  bash -n "$script" || fail "bash -n refuses the script"
  tr -d '\n' <"$script" | LC_ALL=C grep -q '[[:cntrl:]]' &&
    fail "a raw control character in the script:"$'\n'"$(cat -A "$script")"
  # sbatch reads #SBATCH lines up to the first command.
  awk '/^#SBATCH/ && command { late = 1 } !/^#/ && !/^$/ { command = 1 } END { exit late }' \
    "$script" || fail "an #SBATCH line after a command:"$'\n'"$(cat -A "$script")"
  [ "$(grep -c '^#SBATCH' "$script")" -eq 5 ] || fail "expected 5 #SBATCH lines: $(grep '^#SBATCH' "$script")"
  (cd "$work/task" && SLURM_JOB_ID=7 SLURM_ARRAY_JOB_ID=7 SLURM_ARRAY_TASK_ID=1 \
    SLURM_CPUS_PER_TASK=1 bash "$script" >"$work/task.log" 2>&1) ||
    fail "the script failed as array task 1: $(tail -3 "$work/task.log")"
  pwned=$(find "$work" -name PWNED)
  [ -z "$pwned" ] || fail "a command in a value ran: $pwned"
  # Case 1 ran in the hostile directory with both overrides: 3 ms of 2e-7 s.
  grep -q '"steps": 15000' "$dir/phi-0.1_e-0.8/summary.json" 2>/dev/null ||
    fail "array task 1 did not run case 1 for 3 ms: $(tail -3 "$work/task.log")"
  [ ! -e "$dir/phi-0.1_e-0.5" ] || fail "array task 1 ran case 0 as well"
  ;;
emit_slurm_many_cases)
  # tiny.toml with 1002 values of time.duration: one more case than array indices 0-1000.
  {
    sed -n '1,/^\[\[axis\]\]/p' "$studies/tiny.toml" | sed '$d' |
      sed "s|^base = .*|base = \"$source/scenes/default.toml\"|"
    echo '[[axis]]'
    echo 'name = "T"'
    echo 'key = "time.duration"'
    awk 'BEGIN { printf "values = ["; for (k = 0; k < 1002; ++k) printf "%s%.7f", k ? ", " : "", 0.004 + k * 1e-7; print "]" }'
  } >"$work/many.toml"
  "$granshock" study "$work/many.toml" --out "$out" --emit slurm >/dev/null 2>"$work/stderr" ||
    fail "--emit slurm failed: $(cat "$work/stderr")"
  grep -qx '#SBATCH --array=0-1001' "$out/study.slurm" || fail "array range: $(grep array "$out/study.slurm")"
  [ "$(grep -vc '^Kokkos::' "$work/stderr")" -eq 1 ] || fail "expected one warning line: $(cat "$work/stderr")"
  grep -q "warning: 1002 array tasks (0-1001) exceed Slurm's default MaxArraySize of 1001 .* sbatch --array=0-1000 '[^']*study.slurm' 0, then sbatch --array=0-0 '[^']*study.slurm' 1001 (docs/study.md" \
    "$work/stderr" || fail "the warning: $(cat "$work/stderr")"
  ;;
summary_extremes)
  "$granshock" study "$studies/tiny.toml" --out "$out" --quiet --case 0 2>"$work/stderr" ||
    fail "--case 0 failed: $(cat "$work/stderr")"
  case0=$out/phi-0.1_e-0.5
  /usr/bin/python3 -c 'import json, sys; p = sys.argv[1]; s = json.load(open(p)); s["wall_seconds"] = 1e300; json.dump(s, open(p, "w"))' \
    "$case0/summary.json"
  "$granshock" study "$studies/tiny.toml" --out "$out" --emit slurm >/dev/null 2>"$work/stderr" ||
    fail "--emit slurm failed: $(cat "$work/stderr")"
  grep -qx '#SBATCH --time=365-00:00:00' "$out/study.slurm" ||
    fail "the time limit: $(grep -- --time "$out/study.slurm")"
  grep -q "warning: the time limit for the largest case .* is not below 365 days" "$work/stderr" ||
    fail "no warning of the clamped limit: $(cat "$work/stderr")"
  # 200 000 levels: the parser's callers overflowed the stack (exit 139).
  /usr/bin/python3 -c 'import sys; n = 200000; open(sys.argv[1], "w").write("{\"a\": " * n + "1" + "}" * n)' \
    "$work/deep.json"
  cp "$work/deep.json" "$case0/summary.json"
  expect_deep() {  # LABEL PATH COMMAND...: exit 2 and one line naming PATH
    local label=$1 path=$2
    shift 2
    "$@" >/dev/null 2>"$work/stderr"
    local code=$?
    [ $code -eq 2 ] || fail "$label: exit code $code, expected 2: $(head -c 300 "$work/stderr")"
    [ "$(grep -vc '^Kokkos::' "$work/stderr")" -eq 1 ] || fail "$label: expected one line: $(head -c 300 "$work/stderr")"
    grep -qx "granshock: error: $path: JSON nested deeper than 64 levels" "$work/stderr" ||
      fail "$label: the message: $(head -c 300 "$work/stderr")"
  }
  expect_deep "study --collect" "$case0/summary.json" "$granshock" study "$studies/tiny.toml" --out "$out" --collect
  expect_deep "study --emit slurm" "$case0/summary.json" "$granshock" study "$studies/tiny.toml" --out "$out" --emit slurm
  expect_deep "fields" "$case0/summary.json" "$granshock" fields "$case0"
  expect_deep "run --accuracy-table" "$work/deep.json" "$granshock" run "$source/scenes/default.toml" \
    --accuracy 1% --accuracy-table "$work/deep.json" --dry-run --out "$work/never"
  ;;
*)
  echo "unknown check $check"
  exit 2
  ;;
esac
[ $status -eq 0 ] && echo "$check: passed"
exit $status

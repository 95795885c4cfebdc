#!/bin/bash
# What a run directory says afterwards (docs/output_format.md, "The run's log and build"):
# log.txt holds what stderr showed, with times, and each leg's first line; summary.json
# holds the warnings, the build (also in run.h5) and, after a --resume that ran no step,
# the rate of the leg that did; `granshock --version` prints the build.
# Usage: run_log.sh GRANSHOCK SCENE
set -u
granshock=$1 scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# A small channel, 4 ms, at a time step the guard warns about (t_c/6: docs/stability.md).
tiny=(--no-figures --set 'domain.width="40 d"' --set 'domain.length="60 d"'
  --set 'obstacle.diameter="10 d"' --set 'obstacle.centre=["20 d", "35 d"]'
  --set time.duration=0.004 --set time.production_start=0.002 --set output.sample_every=20
  --set output.snapshot_interval=0.002 --set output.checkpoint_interval=0.001
  --set output.progress_interval=0.01 --set time.dt=5e-7)

"$granshock" --version >"$dir/version" 2>&1 || fail "--version: exit status $?"
cat "$dir/version"
grep -Eq '^granshock [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{40}(-dirty)?|unknown), ' \
  "$dir/version" || fail "--version does not name the version and commit"

"$granshock" run "$scene" "${tiny[@]}" --out "$dir/run" --stop-after-steps 4000 \
  >"$dir/out1" 2>"$dir/err1" || { cat "$dir/err1"; fail "the first leg"; }
"$granshock" run "$scene" "${tiny[@]}" --out "$dir/run" --resume >"$dir/out2" 2>"$dir/err2" ||
  { cat "$dir/err2"; fail "the second leg"; }
cp "$dir/run/summary.json" "$dir/finished.json"
# A --resume of the finished run runs no step: the rate of the leg that ran stays.
"$granshock" run "$scene" "${tiny[@]}" --out "$dir/run" --resume >"$dir/out3" 2>"$dir/err3" ||
  { cat "$dir/err3"; fail "the resume of a finished run"; }
cat "$dir/err1" "$dir/err2" "$dir/err3" >"$dir/stderr"

/usr/bin/python3 - "$dir" <<'PY' || fail "see above"
import json, re, sys
import h5py

d = sys.argv[1]
problems = []
def expect(ok, what):
    if not ok:
        problems.append(what)

log = open(d + "/run/log.txt").read().splitlines()
stamp = re.compile(r"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z  (.*)$")
texts = []
for line in log:
    m = stamp.match(line)
    expect(m is not None, "a log line without its time: %r" % line)
    texts.append(m.group(1) if m else line)
stderr = [l for l in open(d + "/stderr").read().splitlines() if not l.startswith("Kokkos")]
for line in stderr:
    expect(line in texts, "a stderr line missing from log.txt: %r" % line)
legs = [t for t in texts if re.match(r"granshock \S+ \(commit .*\): run .* on 1 process$", t)]
expect(len(legs) == 3 and "(new)" in legs[0] and "(--resume)" in legs[1],
       "not one first line per leg: %r" % legs)
header = [t.split() for t in texts if t.split()[:3] == ["Step", "Time", "Particles"]]
expect(header, "no thermo header in log.txt")
expect(any(re.match(r"^ *\d+ +[\d.e+-]+ +\d+ +\d+ ", t) for t in texts), "no thermo row in log.txt")
# thermo.txt: the same columns, read by pandas as it is; one comment per leg, the steps
# growing within each leg, the last row the run's end.
import pandas
table = pandas.read_csv(d + "/run/thermo.txt", sep=r"\s+", comment="#")
expect(header and list(table.columns) == header[0], "thermo.txt columns %r" % list(table.columns))
legs_noted = [l for l in open(d + "/run/thermo.txt") if l.startswith("# ")]
expect(len(legs_noted) == 3, "thermo.txt notes %d legs, not 3" % len(legs_noted))
expect(len(table) >= 2 and table["Step"].iloc[-1] == 8000, "thermo.txt rows %r" % table.tail(3))
expect(table["Particles"].min() > 0 and table["KinEng"].min() > 0, "thermo.txt values")
expect(any("stopped after 4000 steps" in t for t in texts), "no stop line in log.txt")
expect(any(" done: " in t for t in texts), "no done line in log.txt")

warned = [l[len("granshock: warning: "):] for l in stderr if l.startswith("granshock: warning: ")]
expect(warned, "the time step was not warned about on stderr")
summary = json.load(open(d + "/run/summary.json"))
expect(summary.get("warnings") == sorted(set(warned), key=warned.index),
       "summary.json warnings %r, stderr %r" % (summary.get("warnings"), warned))
build = summary.get("build", {})
for key in ("version", "commit", "compiler", "build_type", "march", "kokkos",
            "default_execution_space"):
    expect(isinstance(build.get(key), str) and build[key], "summary.json build.%s" % key)
with h5py.File(d + "/run/run.h5", "r") as f:
    stored = f["h5md/creator"].attrs.get("build")
    stored = stored.decode() if isinstance(stored, bytes) else stored
    expect(stored is not None and json.loads(stored) == build, "run.h5 /h5md/creator@build")
# What the time loop launched (docs/cuda.md, "Launches per step"): the first leg's counts;
# a host build's copies never cross memory spaces.
first = json.load(open(d + "/finished.json"))
expect(first.get("kernel_launches_per_step", 0) > 0, "no kernel launches counted")
expect(0 <= first.get("reductions_per_step", -1) <= first["kernel_launches_per_step"],
       "reductions_per_step %r" % first.get("reductions_per_step"))
expect(first.get("device_to_host_copies_per_step") == 0, "copies across spaces on the host")
expect(0 < first.get("host_reads_per_step", -1) <= first["kernel_launches_per_step"] +
       first["deep_copies_per_step"], "host_reads_per_step %r" % first.get("host_reads_per_step"))
expect("fences_per_step" in first, "no fences_per_step key")
finished = json.load(open(d + "/finished.json"))
expect(finished["particle_steps_per_second"] > 0, "the finished run measured no rate")
expect(summary["particle_steps_per_second"] == finished["particle_steps_per_second"],
       "--resume of the finished run changed the rate from %r to %r"
       % (finished["particle_steps_per_second"], summary["particle_steps_per_second"]))
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
PY

# A refused --resume (a scene key changed) leaves the log as it was.
cp "$dir/run/log.txt" "$dir/log.before"
"$granshock" run "$scene" "${tiny[@]}" --set contact.restitution=0.6 --out "$dir/run" --resume \
  >/dev/null 2>&1
[ $? -eq 2 ] || fail "a --resume with another scene was not refused"
cmp -s "$dir/log.before" "$dir/run/log.txt" || fail "a refused --resume wrote to log.txt"
# --overwrite starts a new log.
"$granshock" run "$scene" "${tiny[@]}" --out "$dir/run" --overwrite --quiet >/dev/null 2>&1 ||
  fail "the --overwrite run"
[ "$(grep -c ': run ' "$dir/run/log.txt")" -eq 1 ] || fail "--overwrite kept the old log"
echo "PASS"

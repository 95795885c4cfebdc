#!/usr/bin/python3
"""The hostile-user probe (docs/stability.md, "The hostile-user probe").

Plays a hostile but realistic user against a built granshock, case after case, and checks
the rules every command must keep whatever it is given (README, "Your files are safe";
docs/output_format.md, "The run directory"):

- it ends: no case may hang (each has a time limit);
- it ends cleanly: exit code 0, or 2 with exactly one line on stderr, or 128+signal after a
  signal; never 3 (internal error), 4 (blew up on input that validation should have caught)
  or a crash;
- files that are not granshock's stay as they were, links are never written through, and
  nothing a user typed runs as a command;
- what a message promises holds: "continue with --resume" resumes, and a resumed run ends
  where an uninterrupted one does.

Categories: directories and symbolic links for every command that writes (dirs), FIFOs
and other special files for every input (special), deeply nested inputs (nesting), species,
memory and thread limits (limits), values that validation must refuse (values), signals
during setup and analysis (signals), file-size limits during a run (disk), and text that
reaches an emitted script or table (scripts).

Usage: hostile_user.py GRANSHOCK SOURCE_DIR [--deep] [--only CATEGORY[,CATEGORY...]]
--deep (or GRANSHOCK_PROBE_DEEP=1) runs the whole matrix (every output name for every
writer, more file-size limits and signal times); the default is a selection of every
category that runs in about a minute on 2 cores (with figures only in the categories whose
checks cover them: WITH_FIGURES).
"""

import argparse
import csv
import hashlib
import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time

KOKKOS_NOISE = re.compile(r"^(Kokkos::OpenMP::initialize WARNING|  )")

# A small, fast version of scenes/default.toml (the tiny study's channel: 40 d x 60 d,
# a cylinder of 10 d, 4 ms simulated; seconds on one thread).
TINY = [
    "domain.width=40 d", "domain.length=60 d", "obstacle.diameter=10 d",
    'obstacle.centre=["20 d", "35 d"]', "time.duration=0.004", "time.production_start=0.002",
    "output.sample_every=20", "output.snapshot_interval=0.002",
    "output.checkpoint_interval=0.001", "output.series_interval=0.0005",
    "output.progress_interval=1000",
]

# Every path a run or `granshock fields` writes in a run directory (docs/output_format.md).
ATOMIC_OUTPUTS = ["run.xmf", "checkpoint.h5", "summary.json", "fields.h5", "fields.xmf",
                  "detachment_convergence.csv"]
FIGURES = ["figures/solid_fraction.png", "figures/temperature.png", "figures/mach.png",
           "figures/stagnation_profiles.png"]
# log.txt: appended to, never replaced (cases/bow_shock/run_log.hpp).
OUTPUTS = ["run.h5", "log.txt"] + ATOMIC_OUTPUTS + [n + ".tmp" for n in ATOMIC_OUTPUTS] + FIGURES

# The categories whose checks cover what the figures write (a link in place of figures/ or
# of a PNG, a full disk or a signal while they are drawn) draw them, as a user's commands
# do by default; the others run with GRANSHOCK_FIGURES=0 (docs/fields.md, "figures/"):
# none of their checks looks at the figures, and drawing them took most of their time.
WITH_FIGURES = {"dirs", "disk", "signals"}

HOSTILE_TEXT = ["x\ntouch PWNED #", "x\rtouch PWNED #", "$(touch PWNED)", "`touch PWNED`",
                "x'; touch PWNED; '", 'x"; touch PWNED; "', "x%n%s%A", "x\ttab"]


def sha(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        h.update(f.read())
    return h.hexdigest()


def tree_digest(root):
    """Every file under root with its content hash, and every link with its target."""
    digest = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            p = os.path.join(dirpath, name)
            st = os.lstat(p)
            if stat.S_ISLNK(st.st_mode):
                digest[p] = "link:" + os.readlink(p)
            elif stat.S_ISREG(st.st_mode):
                digest[p] = sha(p)
            else:
                digest[p] = "dir" if stat.S_ISDIR(st.st_mode) else "special"
    return digest


class Probe:
    def __init__(self, granshock, source, deep):
        self.granshock = os.path.abspath(granshock)
        self.source = os.path.abspath(source)
        self.scene = os.path.join(self.source, "scenes", "default.toml")
        self.deep = deep
        self.root = tempfile.mkdtemp(prefix="granshock-probe-")
        self.passed = self.failed = self.refusals = self.accepted = 0
        self.failures = []
        self.env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false",
                        GRANSHOCK_FIGURES="0")
        self.finished_run = None
        self.stopped_run = None
        self.finished_study = None

    # --- running one command ------------------------------------------------------------
    def granshock_cmd(self, *args):
        return [self.granshock] + [str(a) for a in args]

    def tiny(self):
        out = []
        for s in TINY:
            out += ["--set", s]
        return out

    def run(self, argv, cwd, timeout=60, env=None, preexec=None, signal_after=None):
        """Runs argv; returns (code, stdout, own stderr lines, seconds) or code None on a hang."""
        e = dict(self.env)
        if env:
            e.update(env)
        start = time.monotonic()
        p = subprocess.Popen(argv, cwd=cwd, env=e, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             stdin=subprocess.DEVNULL, preexec_fn=preexec, start_new_session=True)
        if signal_after is not None:
            sig, delay = signal_after
            try:
                p.wait(timeout=delay)
            except subprocess.TimeoutExpired:
                p.send_signal(sig)
        try:
            out, err = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return None, "", ["(killed after %g s)" % timeout], time.monotonic() - start
        lines = [l for l in err.decode(errors="replace").splitlines() if not KOKKOS_NOISE.match(l)]
        return p.returncode, out.decode(errors="replace"), lines, time.monotonic() - start

    # --- bookkeeping ------------------------------------------------------------------------
    def case(self, category, name, argv, cwd, expect=("ok", "refuse"), timeout=60, env=None,
             guard=(), after=None, preexec=None, signal_after=None, pattern=None,
             unstarted=None):
        """One probe case. expect: the answers that are acceptable ('ok', 'refuse', 'signal',
        'partial': exit 1 of a study that lists its unfinished cases, docs/study.md).
        guard: paths whose contents (recursively) must not change. after(code, out, lines)
        returns a list of further problems. pattern: a regex the refusal line must match.
        unstarted: with signal_after, a path the command creates first; a death by the signal
        itself is accepted while that path does not exist (the signal came while the dynamic
        loader was still mapping the libraries, before any of granshock's code ran: nothing
        was written, and nothing can be said)."""
        if category in WITH_FIGURES:
            env = dict(env or {}, GRANSHOCK_FIGURES="1")
        before = {}
        for g in guard:
            before.update(tree_digest(g) if os.path.isdir(g) and not os.path.islink(g)
                          else {g: sha(g) if os.path.isfile(g) and not os.path.islink(g)
                                else "link:" + os.readlink(g)})
        code, out, lines, seconds = self.run(argv, cwd, timeout, env, preexec, signal_after)
        problems = []
        if code is None:
            problems.append("hung: no answer within %g s" % timeout)
        elif code == 0:
            self.accepted += 1
            if "ok" not in expect:
                problems.append("accepted (exit 0), expected a refusal")
        elif code == 2:
            self.refusals += 1
            if "refuse" not in expect:
                problems.append("refused (exit 2), expected success: " + " | ".join(lines))
            elif len(lines) != 1:
                problems.append("refusal of %d lines on stderr, expected one: %s"
                                % (len(lines), " | ".join(lines[:6])))
            elif pattern and not re.search(pattern, lines[0]):
                problems.append("refusal does not match /%s/: %s" % (pattern, lines[0]))
        elif code == 1 and "partial" in expect:
            if not any("not finished" in l or "failed" in l for l in lines):
                problems.append("exit code 1 without a list of unfinished cases: "
                                + " | ".join(lines[-3:]))
        elif code > 128 and "signal" in expect and signal_after and code == 128 + signal_after[0]:
            if len(lines) != 1:
                problems.append("stopped by a signal with %d lines on stderr: %s"
                                % (len(lines), " | ".join(lines[:6])))
        elif (signal_after and unstarted and code == -signal_after[0] and "signal" in expect
              and not os.path.lexists(unstarted)):
            pass
        elif code < 0 or code > 128:
            problems.append("died by signal %d: %s" % (abs(code) if code < 0 else code - 128,
                                                       " | ".join(lines[-3:])))
        else:
            problems.append("exit code %d: %s" % (code, " | ".join(lines[-3:])))
        for g, h in before.items():
            try:
                now = ("link:" + os.readlink(g)) if os.path.islink(g) else (
                    sha(g) if os.path.isfile(g) else ("dir" if os.path.isdir(g) else "special"))
            except FileNotFoundError:
                now = "missing"
            if now != h:
                problems.append("a file that is not granshock's changed: %s" % g)
        for dirpath, _, filenames in os.walk(self.root):
            if "PWNED" in filenames:
                problems.append("a command from the input ran: %s" % os.path.join(dirpath, "PWNED"))
                os.remove(os.path.join(dirpath, "PWNED"))
        if after and code is not None:
            problems += after(code, out, lines) or []
        label = "%s/%s" % (category, name)
        if problems:
            self.failed += 1
            self.failures.append(label)
            print("FAIL %s (%.1f s): %s" % (label, seconds, "; ".join(problems)), flush=True)
        else:
            self.passed += 1
            answer = {0: "ok", 2: "refused"}.get(code, "exit %s" % code)
            if code is not None and code < 0:
                answer = "killed by signal %d before it started; nothing written" % -code
            detail = (": " + lines[0][:150]) if code == 2 and lines else ""
            print("ok   %s (%.1f s, %s%s)" % (label, seconds, answer, detail), flush=True)
        return code, out, lines

    def workdir(self, name):
        d = tempfile.mkdtemp(prefix=name.replace("/", "_")[:40] + "-", dir=self.root)
        return d

    def victim(self, where, name="victim.txt"):
        """A user's file outside every run directory."""
        os.makedirs(where, exist_ok=True)
        p = os.path.join(where, name)
        with open(p, "w") as f:
            f.write("a user's own file: granshock must never change it\n")
        return p

    # --- fixtures -----------------------------------------------------------------------------
    def fixtures(self):
        base = os.path.join(self.root, "fixtures")
        os.makedirs(base)
        run = os.path.join(base, "finished")
        # With its figures: dirs puts links in their place in copies of this run.
        code, _, lines, _ = self.run(self.granshock_cmd("run", self.scene, "--out", run, "--quiet",
                                                        *self.tiny()), base, timeout=300,
                                     env={"GRANSHOCK_FIGURES": "1"})
        if code != 0:
            sys.exit("probe: the tiny run failed (%s): %s" % (code, " | ".join(lines)))
        self.finished_run = run
        stopped = os.path.join(base, "stopped")
        code, _, lines, _ = self.run(self.granshock_cmd("run", self.scene, "--out", stopped,
                                                        "--quiet", "--stop-after-steps", 5000,
                                                        *self.tiny()), base, timeout=300)
        if code != 0:
            sys.exit("probe: the stopped tiny run failed (%s): %s" % (code, " | ".join(lines)))
        self.stopped_run = stopped

    def copy_run(self, which, where):
        dest = os.path.join(where, "run")
        shutil.copytree(which, dest, symlinks=True)
        return dest

    # --- dirs: directories and links for every command that writes --------------------------
    def dirs(self):
        names = OUTPUTS if self.deep else ["run.h5", "log.txt", "fields.h5", "fields.xmf.tmp",
                                           "summary.json",
                                           "summary.json.tmp", "detachment_convergence.csv",
                                           "figures/mach.png"]
        for writer in ("run", "fields"):
            for name in names:
                w = self.workdir("dirs")
                run = self.copy_run(self.finished_run, w)
                user = os.path.join(w, "home")
                target = self.victim(user, "bashrc")
                p = os.path.join(run, name)
                if os.path.lexists(p):
                    os.remove(p)
                os.makedirs(os.path.dirname(p), exist_ok=True)
                os.symlink(target, p)
                argv = (self.granshock_cmd("run", self.scene, "--out", run, "--overwrite",
                                           "--quiet", *self.tiny())
                        if writer == "run" else self.granshock_cmd("fields", run))
                self.case("dirs", "%s-through-link-%s" % (writer, name), argv, w, guard=[user],
                          timeout=120)
            # The figures directory as a link to a user's directory.
            w = self.workdir("dirs")
            run = self.copy_run(self.finished_run, w)
            user = os.path.join(w, "pictures")
            self.victim(user, "mach.png")
            shutil.rmtree(os.path.join(run, "figures"))
            os.symlink(user, os.path.join(run, "figures"))
            argv = (self.granshock_cmd("run", self.scene, "--out", run, "--overwrite", "--quiet",
                                       *self.tiny())
                    if writer == "run" else self.granshock_cmd("fields", run))
            self.case("dirs", "%s-figures-is-a-link" % writer, argv, w, guard=[user], timeout=120)

        # fields --out into a user's directory, a link to one, a file, and a new one.
        for kind in ("user-dir", "link-to-user-dir", "user-file", "new", "empty"):
            w = self.workdir("dirs")
            run = self.copy_run(self.finished_run, w)
            user = os.path.join(w, "home")
            self.victim(user, "fields.h5")
            self.victim(user, "summary.json")
            os.makedirs(os.path.join(user, "figures"))
            self.victim(os.path.join(user, "figures"), "mach.png")
            out = {"user-dir": user, "link-to-user-dir": os.path.join(w, "link"),
                   "user-file": os.path.join(user, "summary.json"),
                   "new": os.path.join(w, "new"), "empty": os.path.join(w, "empty")}[kind]
            if kind == "link-to-user-dir":
                os.symlink(user, out)
            if kind == "empty":
                os.makedirs(out)
            expect = ("ok",) if kind in ("new", "empty") else ("refuse",)
            self.case("dirs", "fields-out-" + kind, self.granshock_cmd("fields", run, "--out", out),
                      w, expect=expect, guard=[user, run], timeout=120)

        # A refused --overwrite deletes nothing: a user's folder where an output goes.
        w = self.workdir("dirs")
        run = self.copy_run(self.finished_run, w)
        os.remove(os.path.join(run, "fields.h5"))
        self.victim(os.path.join(run, "fields.h5"), "notes.txt")
        self.case("dirs", "overwrite-with-a-folder-in-place-of-fields.h5",
                  self.granshock_cmd("run", self.scene, "--out", run, "--overwrite", "--quiet",
                                     *self.tiny()),
                  w, expect=("refuse",), guard=[run], timeout=120)

        # A marker of 0 bytes (a full disk at the claim) does not block the directory for good.
        w = self.workdir("dirs")
        run = os.path.join(w, "run")
        os.makedirs(run)
        open(os.path.join(run, ".granshock-run"), "w").close()
        self.case("dirs", "empty-marker",
                  self.granshock_cmd("run", self.scene, "--out", run, "--overwrite", "--quiet",
                                     *self.tiny()), w, expect=("ok",), timeout=120)

        # Every command that takes --out refuses a user's non-empty directory.
        for command in ("run", "study", "study-emit", "tradeoff"):
            w = self.workdir("dirs")
            user = os.path.join(w, "home")
            self.victim(user, "thesis.tex")
            study = os.path.join(self.source, "tests", "study", "tiny.toml")
            argv = {"run": self.granshock_cmd("run", self.scene, "--out", user, "--quiet",
                                              *self.tiny()),
                    "study": self.granshock_cmd("study", study, "--out", user, "--quiet"),
                    "study-emit": self.granshock_cmd("study", study, "--out", user, "--emit",
                                                     "slurm"),
                    "tradeoff": self.granshock_cmd("tradeoff", self.scene, "--out", user, "--quiet",
                                                   *self.tiny())}[command]
            self.case("dirs", command + "-into-a-user-directory", argv, w, expect=("refuse",),
                      guard=[user], timeout=120)

    # --- special: FIFOs and special files as inputs ------------------------------------------
    def special(self):
        def fifo(path):
            os.mkfifo(path)
            return path

        study = os.path.join(self.source, "tests", "study", "tiny.toml")
        cases = {
            "scene-fifo": lambda w: self.granshock_cmd("run", fifo(os.path.join(w, "s.toml")),
                                                       "--dry-run"),
            "scene-fifo-link": lambda w: (fifo(os.path.join(w, "f")),
                                          os.symlink(os.path.join(w, "f"),
                                                     os.path.join(w, "s.toml")),
                                          self.granshock_cmd("run", os.path.join(w, "s.toml"),
                                                             "--dry-run"))[-1],
            "scene-dev-zero": lambda w: self.granshock_cmd("run", "/dev/zero", "--dry-run"),
            "scene-dev-null": lambda w: self.granshock_cmd("run", "/dev/null", "--dry-run"),
            "scene-directory": lambda w: self.granshock_cmd("run", w, "--dry-run"),
            "study-fifo": lambda w: self.granshock_cmd("study", fifo(os.path.join(w, "s.toml")),
                                                       "--dry-run"),
            "tradeoff-scene-fifo": lambda w: self.granshock_cmd(
                "tradeoff", fifo(os.path.join(w, "s.toml")), "--dry-run"),
            "accuracy-table-fifo": lambda w: self.granshock_cmd(
                "run", self.scene, "--dry-run", "--accuracy", "5%", "--accuracy-table",
                fifo(os.path.join(w, "trade.json"))),
            "accuracy-table-dev-zero": lambda w: self.granshock_cmd(
                "run", self.scene, "--dry-run", "--accuracy", "5%", "--accuracy-table",
                "/dev/zero"),
        }
        for name, make in cases.items():
            w = self.workdir("special")
            self.case("special", name, make(w), w, expect=("refuse",), timeout=20)

        for name in ("checkpoint.h5", "run.h5"):
            w = self.workdir("special")
            run = self.copy_run(self.stopped_run, w)
            os.remove(os.path.join(run, name))
            os.mkfifo(os.path.join(run, name))
            self.case("special", "resume-%s-fifo" % name,
                      self.granshock_cmd("run", self.scene, "--out", run, "--resume", "--quiet",
                                         *self.tiny()), w, expect=("refuse",), timeout=20)
        for name in ("run.h5", "summary.json"):
            w = self.workdir("special")
            run = self.copy_run(self.finished_run, w)
            os.remove(os.path.join(run, name))
            os.mkfifo(os.path.join(run, name))
            self.case("special", "fields-%s-fifo" % name, self.granshock_cmd("fields", run), w,
                      expect=("refuse",), timeout=20)
        if self.finished_study:
            w = self.workdir("special")
            out = os.path.join(w, "study")
            shutil.copytree(self.finished_study, out, symlinks=True)
            summary = os.path.join(out, "phi-0.1_e-0.5", "summary.json")
            os.remove(summary)
            os.mkfifo(summary)
            self.case("special", "study-collect-summary-fifo",
                      self.granshock_cmd("study", study, "--out", out, "--collect"), w,
                      expect=("ok", "refuse", "partial"), timeout=20)

    # --- nesting ------------------------------------------------------------------------------
    def nesting(self):
        depths = [200000, 50000, 5000] if self.deep else [200000]
        study = os.path.join(self.source, "tests", "study", "tiny.toml")
        for depth in depths:
            for shape, nested in (("arrays", "[" * depth + "]" * depth),
                                  ("objects", '{"a":' * depth + "1" + "}" * depth)):
                w = self.workdir("nesting")
                run = self.copy_run(self.finished_run, w)
                with open(os.path.join(run, "summary.json"), "w") as f:
                    f.write(nested)
                self.case("nesting", "fields-summary-%d-deep-%s" % (depth, shape),
                          self.granshock_cmd("fields", run), w, timeout=30)
                if not self.finished_study:
                    continue
                for mode in ("--collect", "--emit"):
                    w = self.workdir("nesting")
                    out = os.path.join(w, "study")
                    shutil.copytree(self.finished_study, out, symlinks=True)
                    with open(os.path.join(out, "phi-0.1_e-0.5", "summary.json"), "w") as f:
                        f.write(nested)
                    extra = ["--collect"] if mode == "--collect" else ["--emit", "slurm"]
                    self.case("nesting", "study%s-summary-%d-deep-%s" % (mode, depth, shape),
                              self.granshock_cmd("study", study, "--out", out, *extra), w,
                              expect=("ok", "refuse", "partial"), timeout=30)
            nested = "[" * depth + "]" * depth
            w = self.workdir("nesting")
            scene = os.path.join(w, "s.toml")
            with open(self.scene) as f:
                text = f.read()
            with open(scene, "w") as f:
                f.write("deep = " + nested + "\n" + text)
            self.case("nesting", "scene-%d-deep" % depth,
                      self.granshock_cmd("run", scene, "--dry-run"), w, expect=("refuse",),
                      timeout=30)
            # One command-line argument holds at most 128 KiB.
            short = min(depth, 20000)
            for shape, value in (("array", "[" * short + "]" * short),
                                 ("inline-table", "{a=" * short + "1" + "}" * short)):
                self.case("nesting", "set-%d-deep-%s" % (short, shape),
                          self.granshock_cmd("run", self.scene, "--dry-run", "--set",
                                             "inflow.mach=" + value), w, expect=("refuse",),
                          timeout=30)

    # --- limits: species, memory, threads ---------------------------------------------------
    def species_scene(self, w, count):
        """The default scene with its two species replaced by `count` of equal fractions."""
        with open(self.scene) as f:
            text = f.read()
        text = re.sub(r"\[\[species\]\]\n(?:[^\[\n][^\n]*\n|\n)*", "", text)
        extra = ["", "# a scene of %d species" % count]
        for k in range(count):
            extra += ["[[species]]", 'name = "s%d"' % k, 'material = "aluminium"',
                      'diameter = "1 d"', "number_fraction = %.17g" % (1.0 / count), ""]
        path = os.path.join(w, "species.toml")
        with open(path, "w") as f:
            f.write(text + "\n".join(extra) + "\n")
        return path

    def limits(self):
        counts = [300, 2000, 6000] if self.deep else [300, 6000]
        for count in counts:
            w = self.workdir("limits")
            scene = self.species_scene(w, count)
            self.case("limits", "%d-species-dry-run" % count,
                      self.granshock_cmd("run", scene, "--dry-run"), w, timeout=30)
        w = self.workdir("limits")
        for name, sets in {
            "2e8-particles": ["domain.width=20000 d", "domain.length=20000 d"],
            "skin-300-d": ["domain.width=1000 d", "domain.length=1000 d",
                           "numerics.skin=\"300 d\""],
        }.items():
            argv = self.granshock_cmd("run", self.scene, "--out", os.path.join(w, name), "--quiet")
            for s in sets:
                argv += ["--set", s]
            self.case("limits", name, argv, w, expect=("refuse",), timeout=60)
        for threads in ("1000", "100000"):
            self.case("limits", "omp-threads-" + threads, self.granshock_cmd("info"), w,
                      expect=("ok",), env={"OMP_NUM_THREADS": threads}, timeout=60)
        self.case("limits", "collide-discrete-dt-1e-12",
                  self.granshock_cmd("collide", "--pair", "steel-steel", "--speed", "1",
                                     "--restitution-mode", "discrete", "--dt", "1e-12"), w,
                  expect=("refuse",), timeout=30)

    # --- values that validation must refuse before anything runs ----------------------------
    def values(self):
        w = self.workdir("values")
        bad = {
            "centre-nan": 'obstacle.centre=[nan, nan]',
            "centre-inf": 'obstacle.centre=[inf, "35 d"]',
            "restitution-tiny": "contact.restitution=1e-6",
            "restitution-subnormal": "contact.restitution=1e-320",
            "diameter-subnormal": "species.0.diameter=1e-320",
            "units-d-subnormal": "units.d=1e-320",
            "strip-nan": "inflow.strip=nan",
            "species-named-obstacle": "species.0.name=obstacle",
        }
        for name, setting in bad.items():
            out = os.path.join(w, name)
            self.case("values", name,
                      # The bad value last: a later --set of the same key wins.
                      self.granshock_cmd("run", self.scene, "--out", out, "--quiet",
                                         *self.tiny(), "--set", setting),
                      w, expect=("refuse",), timeout=60)
        for name, args in {
            "collide-speed-1e308": ["--pair", "steel-steel", "--speed", "1e308"],
            "collide-vc-1e300": ["--pair", "steel-steel", "--speed", "1", "--model", "hooke",
                                 "--characteristic-velocity", "1e300"],
            "collide-at-1e9": ["--pair", "steel-steel", "--speed", "1", "--at", "1e9,0"],
        }.items():
            self.case("values", name, self.granshock_cmd("collide", *args), w, expect=("refuse",),
                      timeout=30, after=lambda c, o, l: [
                          "the message names a time step or a step count, not the input: " + l[0]]
                      if l and re.search(r"dt = (0|-?nan)|within \d+ steps", l[0]) else [])
        self.case("values", "study-case-minus-one",
                  self.granshock_cmd("study", os.path.join(self.source, "tests", "study",
                                                           "tiny.toml"), "--case", "-1",
                                     "--dry-run"),
                  w, expect=("refuse",), timeout=30,
                  after=lambda c, o, l: ["a number of 20 digits or more in: " + l[0]]
                  if l and re.search(r"\d{20}", l[0]) else [])
        for name, table in {
            "case-is-a-number": '{"cases": [{"case": 5}]}',
            "subnormal-dt": '{"cases": [{"case": "x", "dt_over_tc": 1e-320}]}',
            "not-json": "not json at all",
            "empty": "",
        }.items():
            path = os.path.join(w, name + ".json")
            with open(path, "w") as f:
                f.write(table)
            self.case("values", "accuracy-table-" + name,
                      self.granshock_cmd("run", self.scene, "--dry-run", "--accuracy", "5%",
                                         "--accuracy-table", path), w, expect=("refuse",),
                      timeout=30)

    # --- signals during setup, the loop and the analysis ------------------------------------
    def signals(self):
        delays = [0.01, 0.05, 0.2, 0.5, 1.0, 2.0, 3.0] if self.deep else [0.01, 0.3, 1.5]
        for sig in (signal.SIGTERM, signal.SIGINT):
            for delay in delays:
                w = self.workdir("signals")
                run = os.path.join(w, "run")
                argv = self.granshock_cmd("run", self.scene, "--out", run, "--quiet", *self.tiny())

                def resumes(code, out, lines, run=run, argv=argv):
                    if code != 128 + sig:
                        return []
                    said = " ".join(lines)
                    if "--resume" in said:
                        c, _, l, _ = self.run(argv + ["--resume"], w, timeout=120)
                        if c != 0:
                            return ["said --resume, which then failed (%s): %s"
                                    % (c, " | ".join(l))]
                    else:
                        c, _, l, _ = self.run(argv + ["--overwrite"], w, timeout=120)
                        if c != 0:
                            return ["--overwrite after the signal failed (%s): %s"
                                    % (c, " | ".join(l))]
                    return []
                self.case("signals", "%s-after-%gs" % (signal.Signals(sig).name, delay), argv, w,
                          expect=("ok", "signal"), signal_after=(sig, delay), timeout=120,
                          after=resumes, unstarted=run)

    # --- disk: a file-size limit during a run -------------------------------------------------
    def disk(self):
        limits = [600, 1300, 1350, 1440, 2000, 2600] if self.deep else [1300, 1440, 2600]
        for limit in limits:
            w = self.workdir("disk")
            run = os.path.join(w, "run")
            argv = self.granshock_cmd("run", self.scene, "--out", run, "--quiet", *self.tiny())

            def limited(limit=limit):
                import resource
                resource.setrlimit(resource.RLIMIT_FSIZE, (limit * 1024, limit * 1024))

            def resumes(code, out, lines, run=run, argv=argv):
                if code != 2:
                    return []
                said = " ".join(lines)
                if "--resume" not in said:
                    return []
                c, _, l, _ = self.run(argv + ["--resume"], w, timeout=120)
                if c != 0:
                    return ["said --resume, which then failed (%s): %s" % (c, " | ".join(l))]
                ref = os.path.join(self.finished_run, "checkpoint.h5")
                mine = os.path.join(run, "checkpoint.h5")
                a = subprocess.run(["h5dump", "-d", "/state/position", ref], capture_output=True)
                b = subprocess.run(["h5dump", "-d", "/state/position", mine], capture_output=True)
                if a.returncode == 0 and a.stdout.split(b"\n", 1)[1] != b.stdout.split(b"\n", 1)[1]:
                    return ["the resumed run does not end where an uninterrupted one does"]
                return []
            self.case("disk", "ulimit-f-%dk" % limit, argv, w, preexec=limited, timeout=120,
                      after=resumes)

    # --- scripts and tables: text a user typed -------------------------------------------------
    def study_file(self, w, out=None, name="tiny", sets=(), options=(), one_case=False):
        with open(os.path.join(self.source, "tests", "study", "tiny.toml")) as f:
            text = f.read()
        if one_case:
            text = text[:text.index("[[axis]]")] + (
                '[[axis]]\nname = "phi"\nkey = "inflow.area_fraction"\nvalues = [0.1]\n')
        text = text.replace('base = "../../scenes/default.toml"',
                            "base = %s" % toml_string(self.scene))
        text = text.replace('name = "tiny"', "name = %s" % toml_string(name))
        lines = text.split("\n")
        extra = []
        if out is not None:
            extra.append("out = %s" % toml_string(out))
        i = lines.index("[study]") + 1
        lines[i:i] = extra
        text = "\n".join(lines)
        if sets:
            text = text.replace("[study]\n", "[study]\n", 1)
            text = text.replace('"output.progress_interval=1000"]',
                                '"output.progress_interval=1000", %s]'
                                % ", ".join(toml_string(s) for s in sets))
        if options:
            text += "\n[slurm]\noptions = [%s]\n" % ", ".join(toml_string(o) for o in options)
        path = os.path.join(w, "s.toml")
        with open(path, "w") as f:
            f.write(text)
        return path

    def scripts(self):
        texts = HOSTILE_TEXT if self.deep else HOSTILE_TEXT[:4]
        for k, text in enumerate(texts):
            for where in ("out", "set", "cli-set", "name", "option"):
                w = self.workdir("scripts")
                out = os.path.join(w, "runs", "x" + text)
                kwargs = {"out": out if where == "out" else os.path.join(w, "study")}
                if where == "set":
                    kwargs["sets"] = ["species.0.name=steel" + text]
                if where == "name":
                    kwargs["name"] = "tiny" + text
                if where == "option":
                    kwargs["options"] = ["--comment=" + text]
                study = self.study_file(w, **kwargs)
                argv = self.granshock_cmd("study", study, "--emit", "slurm")
                if where == "cli-set":
                    argv += ["--set", "species.0.name=steel" + text]

                def runs_safely(code, o, lines, w=w):
                    if code != 0:
                        return []
                    scripts = []
                    for dirpath, _, filenames in os.walk(w):
                        scripts += [os.path.join(dirpath, f) for f in filenames
                                    if f == "study.slurm"]
                    if not scripts:
                        return ["no study.slurm written"]
                    # A task number past the study: the script's own command refuses at once,
                    # so that only what the script itself would run is run.
                    env = {"SLURM_ARRAY_TASK_ID": "999999", "SLURM_CPUS_PER_TASK": "1"}
                    c, _, l, _ = self.run(["bash", scripts[0]], w, timeout=60, env=env)
                    problems = []
                    with open(scripts[0]) as f:
                        for line in f:
                            if line.startswith("#SBATCH") and not re.match(r"#SBATCH --\S+", line):
                                problems.append("an #SBATCH line that is not an option: "
                                                + line.strip())
                    return problems
                self.case("scripts", "emit-slurm-%s-%d" % (where, k), argv, w, after=runs_safely,
                          timeout=60)

        if self.finished_study:
            # A case that claims a wall time of 1e300 s, and one of NaN.
            for claim in ("1e300", "NaN", "-5"):
                w = self.workdir("scripts")
                out = os.path.join(w, "study")
                shutil.copytree(self.finished_study, out, symlinks=True)
                summary = os.path.join(out, "phi-0.1_e-0.5", "summary.json")
                with open(summary) as f:
                    text = f.read()
                text = re.sub(r'"wall_seconds": [^,\n]*', '"wall_seconds": ' + claim, text)
                with open(summary, "w") as f:
                    f.write(text)
                study = os.path.join(self.source, "tests", "study", "tiny.toml")

                def sane_time(code, o, lines, out=out):
                    if code != 0:
                        return []
                    with open(os.path.join(out, "study.slurm")) as f:
                        t = re.search(r"^#SBATCH --time=(.*)$", f.read(), re.M)
                    if not t or not re.fullmatch(r"\d+-\d\d:\d\d:00", t.group(1)):
                        return ["time limit %r" % (t.group(1) if t else None)]
                    return []
                self.case("scripts", "emit-slurm-wall-seconds-" + claim,
                          self.granshock_cmd("study", study, "--out", out, "--emit", "slurm"), w,
                          after=sane_time, timeout=60)

        # A study of 10,000 cases warns about Slurm's MaxArraySize.
        w = self.workdir("scripts")
        path = os.path.join(w, "big.toml")
        with open(path, "w") as f:
            f.write("[study]\nname = \"big\"\nbase = %s\n\n[[axis]]\nname = \"e\"\n"
                    "key = \"contact.restitution\"\nvalues = [%s]\n"
                    % (toml_string(self.scene),
                       ", ".join("%.6f" % (0.3 + 0.6 * k / 9999) for k in range(10000))))
        self.case("scripts", "emit-slurm-10000-cases",
                  self.granshock_cmd("study", path, "--out", os.path.join(w, "out"), "--emit",
                                     "slurm"), w, timeout=120,
                  after=lambda c, o, l: [] if c != 0 or any("MaxArraySize" in x for x in l)
                  else ["no warning about Slurm's MaxArraySize for --array=0-9999"])

        # A species name with a comma or a quote reaches study.csv intact; a newline is refused.
        for name in ("st,eel", 'st"eel', "st\neel") if self.deep else ("st,eel", "st\neel"):
            w = self.workdir("scripts")
            study = self.study_file(w, out=os.path.join(w, "out"),
                                    sets=["species.0.name=" + name], one_case=True)

            def csv_ok(code, o, lines, w=w):
                if code != 0:
                    return []
                with open(os.path.join(w, "out", "study.csv"), newline="") as f:
                    rows = list(csv.reader(f))
                widths = {len(r) for r in rows}
                return [] if len(widths) == 1 else ["study.csv rows of %s columns" % sorted(widths)]
            argv = self.granshock_cmd("study", study, "--quiet")
            self.case("scripts", "study-csv-species-%r" % name, argv, w, after=csv_ok, timeout=180)

    # ------------------------------------------------------------------------------------------
    def study_fixture(self):
        out = os.path.join(self.root, "fixtures", "study")
        study = os.path.join(self.source, "tests", "study", "tiny.toml")
        code, _, lines, _ = self.run(self.granshock_cmd("study", study, "--out", out, "--quiet"),
                                     self.root, timeout=300)
        if code != 0:
            sys.exit("probe: the tiny study failed (%s): %s" % (code, " | ".join(lines)))
        self.finished_study = out


def toml_string(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace(
        "\r", "\\r").replace("\t", "\\t") + '"'


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("granshock")
    ap.add_argument("source")
    ap.add_argument("--deep", action="store_true", default=os.environ.get("GRANSHOCK_PROBE_DEEP")
                    == "1")
    ap.add_argument("--only", default="")
    a = ap.parse_args()
    probe = Probe(a.granshock, a.source, a.deep)
    categories = ["dirs", "special", "nesting", "limits", "values", "signals", "disk", "scripts"]
    only = [c for c in a.only.split(",") if c]
    start = time.monotonic()
    try:
        probe.fixtures()
        probe.study_fixture()
        for c in categories:
            if not only or c in only:
                getattr(probe, c)()
    finally:
        shutil.rmtree(probe.root, ignore_errors=True)
    cases = probe.passed + probe.failed
    print("hostile probe%s: %d cases in %.0f s, %d refused with one line, %d accepted"
          % (" (deep)" if a.deep else "", cases, time.monotonic() - start, probe.refusals,
             probe.accepted))
    if probe.failures:
        print("failed: " + ", ".join(probe.failures))
    print("%d passed, %d failed" % (probe.passed, probe.failed))
    return 1 if probe.failed else 0


if __name__ == "__main__":
    sys.exit(main())

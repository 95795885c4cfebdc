#!/usr/bin/python3
"""The hostile-user probe (docs/stability.md, "The hostile-user probe").

Plays a hostile but realistic user against a built granshock, case after case, and checks
the rules every command must keep whatever it is given (docs/output_format.md, "Your files are safe";
docs/output_format.md, "The run directory"):

- it ends: no case may hang (each has a time limit);
- it ends cleanly: exit code 0, or 2 with exactly one line on stderr, or 128+signal after a
  signal; never 3 (internal error), 4 (blew up on input that validation should have caught)
  or a crash;
- files that are not granshock's stay as they were, links are never written through, and
  nothing a user typed runs as a command;
- what a message promises holds: "continue with --resume" resumes, and a resumed run ends
  where an uninterrupted one does.

Categories (--only takes their names):

- dirs: directories and symbolic links in place of every output of every command that writes;
- special: FIFOs and other special files for every input;
- nesting: deeply nested inputs;
- limits: species, memory and thread limits;
- values: values that validation must refuse (a plate as wide as the channel among them);
- signals: signals during setup, the loop and the analysis;
- disk: file-size limits during a run;
- scripts: text that reaches an emitted script or table;
- dumps: hostile LAMMPS dumps and maps for fields --from-dump (sparse and NUL-padded files
  under a memory limit, endless lines, huge atom counts, repeated times and ids, inverted or
  foreign boxes, terminal escapes in what a message quotes, bins of 1e-6 d);
- links: a hard link to a user's file in place of each output of run --resume, fields and
  fields --out, and of the directory's marker: refused, the user's file unchanged;
- race: fields and run --overwrite on one directory at once, and two runs into one new
  directory: one of them is told it is in use, and the two never mix;
- accuracy: malformed --accuracy and --accuracy-table, tables of another version, and the
  note about a capped OMP_NUM_THREADS;
- resume: a refused --resume leaves the run directory as it was, and says why in numbers
  that differ;
- checksums: a flipped byte in run.h5 is refused or accepted, never an internal error or a
  crash (the closing lines count both).

Usage: hostile_user.py GRANSHOCK SOURCE_DIR [--deep] [--only CATEGORY[,CATEGORY...]]
--deep (or GRANSHOCK_PROBE_DEEP=1) runs the whole matrix (every output name for every
writer, more file-size limits and signal times); the default is a selection of every
category that runs in about a minute on 2 cores (with figures only in the categories whose
checks cover them: WITH_FIGURES).
"""

import argparse
import csv
import hashlib
import json
import os
import random
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
# log.txt and thermo.txt: appended to, never replaced (cases/bow_shock/run_log.hpp,
# thermo_table.hpp).
OUTPUTS = ["run.h5", "log.txt", "thermo.txt"] + ATOMIC_OUTPUTS + [n + ".tmp" for n in ATOMIC_OUTPUTS] + FIGURES

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


def dir_state(root):
    """tree_digest of root with every entry's modification time, root's own included: a
    command that refuses leaves it as it was, down to the marker's mtime."""
    state = {p: (h, os.lstat(p).st_mtime_ns) for p, h in tree_digest(root).items()}
    state[root] = ("dir", os.lstat(root).st_mtime_ns)
    return state


# The address space of the dumps cases that must stay bounded however large the dump is or
# claims to be (RLIMIT_AS: the committed dump reads in about 20 MB), and their time.
MEMORY_LIMIT = 2 << 30
DUMP_SECONDS = 5


def bounded_memory():
    import resource
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def terminal_problems(raw, code, limit=2000):
    """What is wrong with a command's raw stderr on a user's terminal: more than `limit`
    bytes, or a control byte (ESC, C1 CSI 0x9b, BEL, CR, DEL, ...) that could move the cursor,
    retitle the window or hide text. A refusal (exit 2) is one line: its only newline ends it."""
    problems = []
    if len(raw) > limit:
        problems.append("%d bytes on stderr (at most %d)" % (len(raw), limit))
    body = raw[:-1] if code == 2 and raw.endswith(b"\n") else raw
    bad = sorted({b for b in body if (b < 0x20 and (b != 0x0a or code == 2)) or b in (0x7f, 0x9b)})
    if bad:
        problems.append("stderr holds the control byte(s) " + " ".join("0x%02x" % b for b in bad))
    return problems


def dataset_storage(path):
    """(dataset, first byte, end) of the bytes every dataset of an HDF5 file stores its data
    in: its contiguous block or each of its chunks; empty when h5py cannot say."""
    spans = []
    try:
        import h5py

        def visit(name, obj):
            if not isinstance(obj, h5py.Dataset):
                return
            offset = obj.id.get_offset()
            if offset is not None:
                spans.append((name, offset, offset + obj.id.get_storage_size()))
            elif obj.chunks:
                for k in range(obj.id.get_num_chunks()):
                    info = obj.id.get_chunk_info(k)
                    spans.append((name, info.byte_offset, info.byte_offset + info.size))
        with h5py.File(path, "r") as f:
            f.visititems(visit)
    except Exception:
        return []
    return spans


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
        self.last_stderr = b""
        self.notes = []  # counts a category reports in the closing lines (checksums)
        self.dump = os.path.join(self.source, "tests", "fields", "dump", "small_bow_shock.dump")
        self.dump_map = os.path.join(self.source, "apps", "bench", "lammps", "dump_map.toml")

    # --- running one command ------------------------------------------------------------
    def granshock_cmd(self, *args):
        return [self.granshock] + [str(a) for a in args]

    def tiny(self):
        out = []
        for s in TINY:
            out += ["--set", s]
        return out

    def start(self, argv, cwd, env=None, preexec=None):
        """Starts argv in the background (collect() waits for it)."""
        e = dict(self.env)
        if env:
            e.update(env)
        return subprocess.Popen(argv, cwd=cwd, env=e, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                                preexec_fn=preexec, start_new_session=True)

    def collect(self, p, timeout):
        """Waits for a started command: (code, stdout, own stderr lines, raw stderr bytes), or
        code None when it hung (it is killed)."""
        try:
            out, err = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return None, "", ["(killed after %g s)" % timeout], b""
        lines = [l for l in err.decode(errors="replace").splitlines() if not KOKKOS_NOISE.match(l)]
        return p.returncode, out.decode(errors="replace"), lines, err

    def run(self, argv, cwd, timeout=60, env=None, preexec=None, signal_after=None):
        """Runs argv; returns (code, stdout, own stderr lines, seconds) or code None on a hang.
        The raw bytes of its stderr stay in self.last_stderr."""
        start = time.monotonic()
        p = self.start(argv, cwd, env, preexec)
        if signal_after is not None:
            sig, delay = signal_after
            try:
                p.wait(timeout=delay)
            except subprocess.TimeoutExpired:
                p.send_signal(sig)
        code, out, lines, self.last_stderr = self.collect(p, timeout)
        return code, out, lines, time.monotonic() - start

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
        # A plate as wide as the periodic channel closes it: no gas passes, nothing to measure.
        self.case("values", "plate-as-wide-as-the-channel",
                  self.granshock_cmd("run", os.path.join(self.source, "scenes", "plate.toml"),
                                     "--dry-run", "--set", 'domain.width="150 d"', "--set",
                                     'obstacle.width="150 d"'),
                  w, expect=("refuse",), pattern=r"'obstacle(\.width)?'", timeout=30)
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

    # --- dumps: hostile LAMMPS dumps and maps for fields --from-dump ------------------------
    def dump_frames(self):
        """The committed dump, frame by frame, each a list of its lines."""
        frames = []
        with open(self.dump) as f:
            for line in f.read().splitlines():
                if line.strip() == "ITEM: TIMESTEP":
                    frames.append([])
                frames[-1].append(line)
        return frames

    def dump_case(self, name, make, map_text=None, file_name="bad.dump", expect=("refuse",),
                  pattern=None, bounded=False, after=None):
        """fields --from-dump of one dump that make(path) writes, with the committed map or
        map_text. Every answer's stderr is safe for a terminal (terminal_problems); a refusal
        leaves no --out behind (docs/fields.md, section 13: every file is read and checked
        before --out is created). bounded: under an address-space limit (MEMORY_LIMIT), and
        within DUMP_SECONDS, whatever the dump's size or its claims."""
        w = self.workdir("dumps")
        dump = os.path.join(w, file_name)
        make(dump)
        map_path = self.dump_map
        if map_text is not None:
            map_path = os.path.join(w, "map.toml")
            with open(map_path, "w") as f:
                f.write(map_text)
        out = os.path.join(w, "out")
        started = time.monotonic()

        def checks(code, o, lines):
            problems = terminal_problems(self.last_stderr, code)
            if code != 0 and os.path.lexists(out):
                problems.append("the refused command left --out behind")
            seconds = time.monotonic() - started
            if bounded and seconds > DUMP_SECONDS:
                problems.append("took %.1f s (at most %g s)" % (seconds, DUMP_SECONDS))
            return problems + (after(code, o, lines) if after else [])
        self.case("dumps", name,
                  self.granshock_cmd("fields", "--from-dump", "lammps", dump, "--map", map_path,
                                     "--out", out, "--no-figures"),
                  w, expect=expect, pattern=pattern, preexec=bounded_memory if bounded else None,
                  timeout=60, after=checks,
                  guard=[map_path] + ([dump] if os.path.getsize(dump) < 64 << 20 else []))

    def dumps(self):
        frames = self.dump_frames()
        with open(self.dump, "rb") as f:
            valid = f.read()
        with open(self.dump_map) as f:
            map_text = f.read()

        def item(frame, name):
            """The index of the line after the frame's `ITEM: name` line."""
            return next(i for i, l in enumerate(frame) if l.startswith("ITEM: " + name)) + 1

        def text(fs):
            return "\n".join(l for frame in fs for l in frame) + "\n"

        def write(content):
            def make(path):
                with open(path, "wb") as f:
                    f.write(content.encode() if isinstance(content, str) else content)
            return make

        def sparse(size, head=b""):
            def make(path):
                write(head)(path)
                os.truncate(path, len(head) + size)
            return make

        # The memory limit alone refuses nothing: the committed dump is read under it.
        self.dump_case("committed-dump-under-the-memory-limit", write(valid), expect=("ok",),
                       bounded=True)
        # A sparse file and a dump padded with NULs (a copy cut short by a full disk): nothing
        # that is not a dump is read whole, into memory or through the disk's holes.
        for size in [200 << 20, 2 << 30] if self.deep else [200 << 20]:
            label = "%dMB" % (size >> 20)
            self.dump_case("sparse-file-" + label, sparse(size), bounded=True)
            self.dump_case("dump-with-a-NUL-tail-" + label, sparse(size, valid), bounded=True)
        longer = r"longer than \d+ bytes"
        self.dump_case("first-line-200KB-no-newline", write("A" * 200000), pattern=longer,
                       bounded=True)
        self.dump_case("timestep-line-100KB-no-newline",
                       write("ITEM: TIMESTEP\n" + "1" * 100000), pattern=longer, bounded=True)
        if self.deep:
            def long_line(path):
                with open(path, "w") as f:
                    for _ in range(100):
                        f.write("A" * (1 << 20))
            self.dump_case("line-100MB-no-newline", long_line, pattern=longer, bounded=True)
        # An atom count no frame can hold, one that fits a long and one that fits no int.
        for count in ("9223372036854775807", "4000000000"):
            first = list(frames[0])
            first[item(first, "NUMBER OF ATOMS")] = count
            self.dump_case("number-of-atoms-" + count, write(text([first] + frames[1:])),
                           pattern="NUMBER OF ATOMS", bounded=True)
        # ITEM: TIME on every frame (dump_modify time yes): the frame's time, not timestep x dt.
        timed = []
        for frame in frames:
            t = int(frame[1].strip()) * 2e-7  # the map's dump.dt
            timed.append(frame[:2] + ["ITEM: TIME", "%.17g" % t] + frame[2:])
        self.dump_case("item-time-on-every-frame", write(text(timed)), expect=("ok",))
        same = [list(frame) for frame in timed]
        same[1][3] = same[0][3]
        self.dump_case("two-timesteps-at-one-time", write(text(same)), pattern="out of order")
        twice = list(frames[0])
        a = item(twice, "ATOMS")
        twice[a + 1] = " ".join([twice[a].split()[0]] + twice[a + 1].split()[1:])
        self.dump_case("atom-id-twice", write(text([twice] + frames[1:])), pattern="twice")
        inverted = list(frames[0])
        inverted[item(inverted, "BOX BOUNDS")] = "1 0"
        self.dump_case("box-lo-above-hi-in-the-first-frame",
                       write(text([inverted] + frames[1:])), pattern="lo < hi",
                       # at the first frame (its line 6, the frame at FILE:1), not later
                       after=lambda c, o, l: ["refused as mixed box sizes, or not at the first "
                                              "frame: " + l[0]]
                       if l and ("mixed box" in l[0] or not re.search(r"line 6\b|:1\b", l[0]))
                       else [])
        # A map of another domain than the dump's box, and a dump written in millimetres.
        narrow = map_text.replace('width = "30 d"', 'width = "20 d"')
        assert narrow != map_text, "the dump map's domain.width is no longer 30 d"
        self.dump_case("map-width-20-d-dump-box-30-d", write(valid), map_text=narrow,
                       pattern=r"\bbox\b")
        mm = []
        for frame in frames:
            frame = list(frame)
            b = item(frame, "BOX BOUNDS")
            for k in range(b, b + 3):
                frame[k] = " ".join("%.17g" % (float(v) * 1000) for v in frame[k].split())
            a = item(frame, "ATOMS")
            columns = frame[a - 1].split()[2:]
            scaled = [columns.index(c) for c in ("x", "y", "z")]
            for k in range(a, len(frame)):
                v = frame[k].split()
                for c in scaled:
                    v[c] = "%.17g" % (float(v[c]) * 1000)
                frame[k] = " ".join(v)
            mm.append(frame)
        self.dump_case("dump-in-millimetres", write(text(mm)), pattern=r"\bbox\b")
        # Terminal escapes and floods in what a message quotes: the dump's lines, its name.
        first = frames[0]
        n = item(first, "NUMBER OF ATOMS") - 1
        a = item(first, "ATOMS")
        rng = random.Random(5)
        garbage = rng.randbytes(5 << 20).replace(b"\n", b"\x1b").replace(b"\0", b"\x9b")
        escapes = {
            "esc-csi-as-the-first-line": write("\x1b[2J\x1b[31mred\x1b[0m\n" + text(frames)),
            "osc-title-in-a-header": write(text([first[:n] + ["\x1b]0;owned title\x07"]
                                                 + first[n:]])),
            "c1-csi-in-a-header": write(text([first[:n]]).encode() + b"\x9b2J \xc2\x9b2J\r\n"),
            "esc-in-an-atom-id": write(text([first[:a] + ["1\x1b[8m 1 0 0 0 0 0 0"]
                                              + first[a + 1:]])),
            "garbage-header-line-60KB": write(text([first[:n]]).encode() + garbage[:60000]
                                              + b"\n"),
            "garbage-header-line-5MB": write(text([first[:n]]).encode() + garbage + b"\n"),
        }
        for name, make in escapes.items():
            self.dump_case(name, make)
        for name, file_name in (("esc-in-the-file-name", "d\x1b]0;owned\x07\x1b[2J.dump"),
                                ("newline-in-the-file-name", "d\ngranshock: error: fake.dump")):
            self.dump_case(name, write(text([first[:a + 3]])), file_name=file_name)
        # A map of bins a millionth of a diameter: refused by the key, not by the memory.
        tiny_bins = re.sub(r'^bin_size = .*$', 'bin_size = "1e-6 d"', map_text, flags=re.M)
        assert tiny_bins != map_text, "the dump map has no bin_size line"
        self.dump_case("map-bin-size-1e-6-d", write(valid), map_text=tiny_bins,
                       pattern=r"numerics\.bin_size", bounded=True)

    # --- links: a hard link in place of every file a command writes ------------------------------
    def links(self):
        """A user's file ~/x with a second name in a run or fields directory: the user's own
        file linked in (ln ~/x RUN/NAME), or a 'backup' of granshock's (ln RUN/NAME ~/x).
        Writing NAME would change ~/x, so each writer refuses, naming the hard link, and ~/x
        stays as it was."""
        deep = self.deep
        base = self.workdir("links")
        fields_out = os.path.join(base, "out")  # what `fields RUN --out OUT` wrote
        code, _, lines, _ = self.run(self.granshock_cmd("fields", self.finished_run, "--out",
                                                        fields_out), base, timeout=120)
        if code != 0:
            sys.exit("probe: fields --out failed (%s): %s" % (code, " | ".join(lines)))
        writers = {
            # writer: (the directory it writes, the output names, the command)
            "resume": (self.stopped_run,
                       OUTPUTS + [".granshock-run"] if deep
                       else ["log.txt", "run.h5", ".granshock-run"],
                       lambda run, out: self.granshock_cmd("run", self.scene, "--out", run,
                                                           "--resume", "--quiet", *self.tiny())),
            "fields": (self.finished_run,
                       OUTPUTS + [".granshock-run"] if deep else ["summary.json", "fields.h5"],
                       lambda run, out: self.granshock_cmd("fields", run)),
            "fields-out": (fields_out,
                           # What `fields --out` writes: not the run's own files (run.h5, the
                           # appended log.txt and thermo.txt, checkpoint.h5), which it never
                           # opens in OUT.
                           [n for n in OUTPUTS
                            if n.split(".")[0] not in ("run", "log", "thermo", "checkpoint")]
                           + [".granshock-fields"] if deep else ["summary.json"],
                           lambda run, out: self.granshock_cmd("fields", run, "--out", out)),
        }
        for writer, (which, names, command) in writers.items():
            for name in names:
                for how in ("user-file-as", "backup-of"):
                    if how == "backup-of" and not os.path.isfile(os.path.join(which, name)):
                        continue
                    w = self.workdir("links")
                    run = self.copy_run(self.finished_run if writer == "fields-out" else which, w)
                    where = run
                    if writer == "fields-out":
                        where = os.path.join(w, "out")
                        shutil.copytree(fields_out, where, symlinks=True)
                    home = os.path.join(w, "home")
                    p = os.path.join(where, name)
                    mine = os.path.join(home, "x")
                    if how == "backup-of":
                        os.makedirs(home)
                        os.link(p, mine)
                    else:
                        self.victim(home, "x")
                        if os.path.lexists(p):
                            os.remove(p)
                        os.makedirs(os.path.dirname(p), exist_ok=True)
                        os.link(mine, p)
                    env = {"GRANSHOCK_FIGURES": "1"} if name.startswith("figures/") else None
                    self.case("links", "%s-%s-%s" % (writer, how, name), command(run, where), w,
                              expect=("refuse",), pattern="hard link", guard=[home], env=env,
                              timeout=120)

    # --- race: two commands on one directory at once --------------------------------------------
    def race(self):
        trials = 8 if self.deep else 3
        with open(os.path.join(self.finished_run, "run.h5"), "rb") as f:
            finished_h5 = hashlib.sha256(f.read()).hexdigest()
        # `granshock fields B &`, then a run --overwrite into B 0.3 s later: fields takes
        # 0.3 s without its figures (the run arrives as it writes) and 2 s with them.
        for k in range(trials):
            w = self.workdir("race")
            run = self.copy_run(self.finished_run, w)
            fields = self.start(self.granshock_cmd("fields", run), w,
                                env={"GRANSHOCK_FIGURES": "1" if k % 2 else "0"})
            time.sleep(0.3)

            def unmixed(code, out, lines, fields=fields, run=run):
                fcode, _, flines, _ = self.collect(fields, 120)
                problems = []
                if fcode is None:
                    return ["the fields command hung"]
                if fcode == 2 and (len(flines) != 1 or "in use" not in flines[0]):
                    problems.append("fields refused other than 'in use': " + " | ".join(flines))
                elif fcode not in (0, 2):
                    problems.append("fields ended with %s: %s" % (fcode, " | ".join(flines[-3:])))
                if code == 2 and sha(os.path.join(run, "run.h5")) != finished_h5:
                    problems.append("the refused run changed run.h5")
                if code == 0 and fcode == 0:
                    # Both went through: only right when fields ended before the run began,
                    # and then --overwrite removed what fields wrote.
                    left = [n for n in ("fields.h5", "fields.xmf", "detachment_convergence.csv",
                                        "figures") if os.path.lexists(os.path.join(run, n))]
                    try:
                        with open(os.path.join(run, "summary.json")) as f:
                            summary = json.load(f)
                        if summary.get("completed") is not False or "delta_over_D" in summary:
                            left.append("summary.json (of the analysis, not the stopped run's)")
                    except (OSError, ValueError) as e:
                        left.append("summary.json (%s)" % e)
                    if left:
                        problems.append("both exited 0 and the stopped run's directory holds "
                                        "the old run's %s: the two mixed" % ", ".join(left))
                return problems
            self.case("race", "fields-then-run-overwrite-%d" % k,
                      self.granshock_cmd("run", self.scene, "--out", run, "--overwrite",
                                         "--quiet", "--stop-after-steps", 100, *self.tiny()),
                      w, pattern="in use", after=unmixed, timeout=120)
        # Two runs started at once on a directory that does not exist yet: one runs, the other
        # is told the directory is in use. 8 ms simulated (0.8 s): the winner still holds the
        # directory when a loser slowed by a busy machine gets there.
        for k in range(trials):
            w = self.workdir("race")
            new = os.path.join(w, "new")
            argv = self.granshock_cmd("run", self.scene, "--out", new, "--quiet", *self.tiny(),
                                      "--set", "time.duration=0.008")
            first = self.start(argv, w)

            def one_runs(code, out, lines, first=first):
                fcode, _, flines, _ = self.collect(first, 120)
                if fcode is None:
                    return ["the first run hung"]
                if sorted([code, fcode]) != [0, 2]:
                    return ["exit codes %s and %s, expected one run (0) and one refusal (2): %s"
                            % (fcode, code, " | ".join(flines[-2:] + lines[-2:]))]
                if fcode == 2 and (len(flines) != 1 or "in use" not in flines[0]):
                    return ["the first run's refusal is not 'in use': " + " | ".join(flines)]
                return []
            self.case("race", "two-runs-into-one-new-directory-%d" % k, argv, w,
                      pattern="in use", after=one_runs, timeout=120)

    # --- accuracy: --accuracy, its tables and the thread count ----------------------------------
    def accuracy(self):
        w = self.workdir("accuracy")
        trade = os.path.join(self.source, "docs", "results", "tradeoff", "paper_d50_u2375",
                             "trade.json")
        with open(trade) as f:
            table = f.read()
        versions = {"version-99": table.replace('"granshock trade table 1"',
                                                '"granshock trade table 99"'),
                    "no-version": re.sub(r'\s*"table": "[^"]*",', "", table, count=1)}
        assert all(t != table for t in versions.values()), "trade.json's \"table\" has moved"
        tables = {}
        for name, text in versions.items():
            tables[name] = os.path.join(w, name + ".json")
            with open(tables[name], "w") as f:
                f.write(text)
        cases = {
            "empty": (["--accuracy", ""], None),
            "table-without-accuracy": (["--accuracy-table", trade], r"--accuracy"),
            "hex-percentage": (["--accuracy", "0x5%"], None),
            "table-version-99": (["--accuracy", "5%", "--accuracy-table",
                                  tables["version-99"]], "version"),
            "table-without-a-version": (["--accuracy", "5%", "--accuracy-table",
                                         tables["no-version"]], "version"),
        }
        for name, (args, pattern) in cases.items():
            self.case("accuracy", name, self.granshock_cmd("run", self.scene, "--dry-run", *args),
                      w, expect=("refuse",), pattern=pattern, timeout=30)
        # The note about a capped OMP_NUM_THREADS quotes what was asked, not its 32-bit wrap
        # (2^32 + 1 wraps to 1). Past 2^64 the OpenMP runtime itself complains, before main.
        for threads in ["99999999999", "4294967297"] if self.deep else ["99999999999"]:
            def quoted(code, out, lines, threads=threads):
                said = " ".join(l for l in lines if "OMP_NUM_THREADS" in l)
                if not said:
                    return ["no note about OMP_NUM_THREADS=%s" % threads]
                if threads not in said or "1215752191" in said:
                    return ["the note does not quote %s: %s" % (threads, said)]
                return []
            self.case("accuracy", "omp-threads-" + threads, self.granshock_cmd("info"), w,
                      expect=("ok",), env={"OMP_NUM_THREADS": threads}, timeout=60, after=quoted)

    # --- resume: a refused --resume leaves the directory as it was -----------------------------
    def resume(self):
        durations = {"shorter": ("0.003", ("refuse",), None),
                     "window-empty": ("0.0001", ("refuse",), r"time\.duration"),
                     "longer-by-1e-11-s": ("0.00400000001", ("ok", "refuse"), None)}
        if self.deep:
            durations["shorter-by-1e-11-s"] = ("0.00399999999", ("refuse",), None)
        for name, (duration, expect, pattern) in durations.items():
            w = self.workdir("resume")
            run = self.copy_run(self.finished_run, w)
            # An empty figures/ (the user deleted the PNGs): a refusal removes no directory.
            for png in FIGURES:
                os.remove(os.path.join(run, png))
            before = dir_state(run)

            def unchanged(code, out, lines, run=run, before=before):
                problems = []
                if code == 2:
                    now = dir_state(run)
                    changed = sorted(p for p in set(before) | set(now)
                                     if before.get(p) != now.get(p))
                    if changed:
                        problems.append("the refusal changed the directory: %s"
                                        % ", ".join(os.path.relpath(p, run) for p in changed))
                    same = re.search(r"= ([-+0-9.e]+) s \(was \1 s\)", lines[0] if lines else "")
                    if same:
                        problems.append("the message shows two equal numbers: " + same.group(0))
                return problems
            self.case("resume", "duration-" + name,
                      self.granshock_cmd("run", self.scene, "--out", run, "--resume", "--quiet",
                                         *self.tiny(), "--set", "time.duration=" + duration),
                      w, expect=expect, pattern=pattern, after=unchanged, timeout=120)

    # --- checksums: a flipped byte in run.h5 ----------------------------------------------------
    def checksums(self):
        flips = 30 if self.deep else 10
        source = os.path.join(self.finished_run, "run.h5")
        size = os.path.getsize(source)
        stored = dataset_storage(source)
        rng = random.Random(20240601)
        counts = {"refused": 0, "accepted": 0}
        unchecked = []  # the datasets that an accepted flip changed
        for _ in range(flips):
            offset = rng.randrange(size)
            w = self.workdir("checksums")
            run = self.copy_run(self.finished_run, w)
            with open(os.path.join(run, "run.h5"), "r+b") as f:
                f.seek(offset)
                byte = f.read(1)[0]
                f.seek(offset)
                f.write(bytes([byte ^ rng.randrange(1, 256)]))
            inside = next((d for d, lo, hi in stored if lo <= offset < hi), None)
            code, _, _ = self.case("checksums", "flip-byte-%d%s" % (offset, " (" + inside + ")"
                                                                   if inside else ""),
                                   self.granshock_cmd("fields", run, "--no-figures"), w,
                                   timeout=60)
            if code == 2:
                counts["refused"] += 1
            elif code == 0:
                counts["accepted"] += 1
                if inside:
                    unchecked.append(inside)
        note = ("checksums: of %d flipped bytes in run.h5, %d refused, %d accepted (%d of them "
                "in the data of %s)" % (flips, counts["refused"], counts["accepted"],
                                        len(unchecked), ", ".join(sorted(set(unchecked))) or "none"))
        print("     " + note, flush=True)
        self.notes.append(note)

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
    categories = ["dirs", "special", "nesting", "limits", "values", "signals", "disk", "scripts",
                  "dumps", "links", "race", "accuracy", "resume", "checksums"]
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
    for note in probe.notes:
        print(note)
    if probe.failures:
        print("failed: " + ", ".join(probe.failures))
    print("%d passed, %d failed" % (probe.passed, probe.failed))
    return 1 if probe.failed else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""The table of docs/scene_keys.md against the program, beyond the keys' names and types
(which tests/scene/test_scene_schema.cpp checks against the schema):

- defaults: every default that is a literal (`0.001`, `"hertz"`, `false`, `"2 d"`) or a
  plain expression of other keys and d_max (`time.duration / 10`, `0.3 d_max`,
  `inflow.velocity`) is what `granshock run SCENE --dry-run` resolves for a scene that does
  not set the key;
- ranges: every numeric range of the "accepted" column (`[a, b]`, `(a, b)`, `[a, b)`,
  `>= a`, `> a`) holds at its ends, through `--dry-run --set`: a closed end is accepted and
  a value just outside it refused; an open end is refused, and a value just inside it
  accepted; a refusal must name the key (exit code 2);
- choices: every name listed for a string key (`hertz, hooke`) is accepted, and a name
  that is not listed is refused (tests/scene/test_choice_names.cpp checks the lists against
  the program's tables of names).

The checks run with `--force`, so that the time-step guard and the contact law's range
(docs/scene_format.md, "Limits") do not decide what a key's own range accepts. Where an
end's acceptance depends on other keys in a way one scene cannot show, the check is skipped
with its reason (SKIPPED below), and the skips are printed; where another key's value makes
the end reachable, the check sets it (CONTEXT below). About 170 dry runs of a few
hundredths of a second each, two at a time: one or two seconds in all.

Usage: check_scene_keys.py GRANSHOCK SOURCE_DIR
Prints one line per failure and per skip, and last "N passed, M failed".
"""
import concurrent.futures
import itertools
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import tomllib

# The smallest scene: the required keys alone (with a cylinder, so that the obstacle's
# defaults are resolved), every other key left to its default.
BASE = """
[[species]]
name = "steel"
material = "steel"
diameter = "1 d"
number_fraction = 0.5
[[species]]
name = "aluminium"
material = "aluminium"
diameter = "1 d"
number_fraction = 0.5
[contact]
restitution = 0.5
[domain]
width = "40 d"
length = "60 d"
[inflow]
area_fraction = 0.1
velocity = 1.0
sigma = 0.1
[time]
dt = 2e-7
duration = 0.01
[obstacle]
diameter = "10 d"
"""

# Scenes for the keys that BASE cannot take (a --set cannot remove a key).
VARIANTS = {
    "base": BASE,
    # inflow.mach instead of inflow.sigma.
    "mach": BASE.replace("sigma = 0.1", "mach = 5.9"),
    # A material of the scene's own, used by nothing, for the materials.NAME keys.
    "material": BASE + """
[materials.glass]
youngs_modulus = 6.3e10
poisson_ratio = 0.23
density = 2500.0
""",
    # The obstacle as a wedge, a plate and a square, for their keys.
    "wedge": BASE.replace('diameter = "10 d"\n', 'shape = "wedge"\nhalf_angle = 30.0\n'
                          'length = "10 d"\n'),
    "plate": BASE.replace('diameter = "10 d"\n', 'shape = "plate"\nwidth = "10 d"\n'
                          'thickness = "4 d"\n'),
    # The laws with parameters, for their keys.
    "hooke": BASE.replace("[contact]\n", '[contact]\nmodel = "hooke"\n'),
    "linear": BASE.replace("[contact]\n", '[contact]\nmodel = "linear"\nstiffness = 1e6\n'),
    "square": BASE.replace('diameter = "10 d"\n', 'shape = "square"\nside = "10 d"\n'),
    # Particles and obstacle of a stiff and light material, whose contacts stay within the
    # contact law's range at 1e4 m/s.
    "hard": BASE.replace('material = "steel"', 'material = "hard"')
                .replace('material = "aluminium"', 'material = "hard"')
            + 'material = "hard"\n[materials.hard]\nyoungs_modulus = 1e13\npoisson_ratio = 0.2\n'
              'density = 1.0\n',
    # A 3-D layer 4 d thick (walls by default; thick enough to be periodic), for the keys
    # of 3-D scenes (docs/scene_format.md, "Three dimensions").
    "three_d": BASE.replace("[[species]]", '[scene]\ndim = 3\n[[species]]', 1)
                   .replace('length = "60 d"\n', 'length = "60 d"\nthickness = "4 d"\n'),
    # One species, whose number fraction is 1.
    "one_species": BASE.replace("""[[species]]
name = "aluminium"
material = "aluminium"
diameter = "1 d"
number_fraction = 0.5
""", "").replace("number_fraction = 0.5", "number_fraction = 1.0"),
}

# How a documented key is set with --set, and in which scene.
SET_AS = {
    "[[species]] name": ("species.0.name", "base"),
    "[[species]] material": ("species.0.material", "base"),
    "[[species]] diameter": ("species.0.diameter", "base"),
    "[[species]] number_fraction": ("species.0.number_fraction", "base"),
    "materials.NAME.youngs_modulus": ("materials.glass.youngs_modulus", "material"),
    "materials.NAME.poisson_ratio": ("materials.glass.poisson_ratio", "material"),
    "materials.NAME.density": ("materials.glass.density", "material"),
    'contact.pairs."a-b".restitution': ("contact.pairs.steel-aluminium.restitution", "base"),
    'contact.pairs."a-b".friction': ("contact.pairs.steel-aluminium.friction", "base"),
    "obstacle.half_angle": ("obstacle.half_angle", "wedge"),
    "obstacle.length": ("obstacle.length", "wedge"),
    "obstacle.rotation": ("obstacle.rotation", "square"),
    "contact.characteristic_velocity": ("contact.characteristic_velocity", "hooke"),
    "contact.stiffness": ("contact.stiffness", "linear"),
    "inflow.mach": ("inflow.mach", "mach"),
    "inflow.mach_at": ("inflow.mach_at", "mach"),
    "domain.z_boundary": ("domain.z_boundary", "three_d"),
}


def species_context(value, end):
    """A species' diameter at an end of its range: units.d moves to the end, so that the
    domain, the obstacle and the other species (all given in d) scale with it."""
    return "base", [f"units.d={end!r}"]


def fraction_context(value, end):
    """A number fraction at an end of its range: the other species takes the rest, or, from
    1 on, the scene has one species."""
    if value >= 0.5:
        return "one_species", []
    return "base", [f"species.1.number_fraction={1 - value!r}"]


def long_window(duration):
    """A window of many samples, for a value that needs them (field sampling: at least 10
    samples per block, 40 particles in an upstream bin; docs/scene_format.md, "Field
    sampling")."""
    return lambda value, end: ("base", [f"time.duration={duration!r}", "output.sample_every=1"])


def slow_flow(value, end):
    """Contacts this soft need a flow slow enough that the softened law's peak overlap stays
    within its range (docs/scene_format.md, "Limits"), and a time step near t_c/20 (0.039 s
    here), so that measuring the effective restitution takes no time."""
    if value < 1e6:
        return "base", []
    return "base", ["inflow.velocity=0.001", "inflow.sigma=0.0001", "time.dt=0.002",
                    "time.duration=10.0", "output.sample_every=1"]


def soft_linear(value, end):
    """A linear contact this soft (1e-3 N/m: t_c = 0.2 s for steel on the obstacle) needs a
    flow slow enough that its peak overlap stays within the law's range, v sqrt(m*/kn) =
    0.03 d at 0.5 mm/s, and a time step near t_c/20, so that measuring the effective
    restitution takes no time."""
    if value >= 1e3:
        return "linear", []
    return "linear", ["inflow.velocity=0.0005", "inflow.sigma=0.00005", "time.dt=0.01",
                      "time.duration=100.0", "output.sample_every=1"]


def hypervelocity(value, end):
    """An inflow of 1e4 m/s: the paper's materials pass through each other there (the
    effective restitution cannot be measured, even with --force), a stiff and light one does
    not, at a step of t_c/20 (2.5e-9 s at 2e4 m/s)."""
    if value < 1e3:
        return "base", []
    return "hard", ["time.dt=1e-10", "time.duration=1e-05", "output.sample_every=1"]


# Other keys an end's check sets, by the documented key: f(value, end) -> (scene, [--set]).
CONTEXT = {
    "[[species]] diameter": species_context,
    "[[species]] number_fraction": fraction_context,
    "inflow.area_fraction": long_window(2.0),
    "output.blocks": long_window(0.05),
    "contact.softening": slow_flow,
    "contact.stiffness": soft_linear,
    "inflow.velocity": hypervelocity,
    "inflow.sigma": hypervelocity,
}

# The scene each listed name of a string key is tried in, where it is not the key's own.
CHOICE_SCENE = {("obstacle.shape", "wedge"): "wedge", ("obstacle.shape", "plate"): "plate",
                ("obstacle.shape", "square"): "square",
                ("contact.model", "linear"): "linear",
                ("inflow.mach_at", "inlet_bins"): "mach"}

# (key, check) -> why it is not made. Checks: "default"; "lower", "upper" (the whole end);
# "lower inside", "upper inside" (the value just inside an open end only).
COUNTS = "refused by the run's count limits (docs/scene_format.md, \"Limits\")"
SKIPPED = {
    ("domain.width", "lower inside"):
        "a width just above 0 is refused by the rule of 3 (d_max + numerics.skin)",
    ("domain.length", "lower inside"):
        "a length just above 0 is refused by the rule inflow.strip < domain.length",
    ("obstacle.half_angle", "lower inside"):
        "a wedge of 1e-9 degrees is narrower than the 3 bins the field sampling needs",
    ("obstacle.half_angle", "upper inside"):
        "a wedge of nearly 90 degrees is wider than any domain (its base is 2 length tan)",
    ("time.duration", "lower inside"): "a run of less than one time step is refused",
    ("time.production_start", "upper inside"):
        "a window of no samples is refused (field sampling)",
    ("output.snapshot_interval", "lower inside"): COUNTS,
    ("output.checkpoint_interval", "lower inside"): COUNTS,
    ("numerics.bin_size", "lower inside"): "a bin must be at least d_max wide",
}

# Keys whose default the resolved scene does not hold under the key's name: the default is
# checked instead by setting it explicitly, which must leave the dry run's output as it was.
NOT_WRITTEN = {
    "inflow.mach_at": "mach",
}

# Keys of one obstacle shape with a default: checked in that shape's scene, where the
# resolved scene holds them (another shape's scene refuses them).
DEFAULT_IN = {
    "obstacle.rotation": "square",
    "contact.characteristic_velocity": "hooke",
    "domain.z_boundary": "three_d",
}

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


class Checker:
    def __init__(self, granshock, source):
        self.granshock = granshock
        self.source = pathlib.Path(source)
        self.work = tempfile.TemporaryDirectory(prefix="granshock-scene-keys-")
        self.scenes = {}
        for name, text in VARIANTS.items():
            path = pathlib.Path(self.work.name) / f"{name}.toml"
            path.write_text(text)
            self.scenes[name] = str(path)
        self.runs = itertools.count()
        self.passed = 0
        self.failed = []
        self.skips = []

    def dry_run(self, scene, sets=()):
        # A directory of its own per dry run: --dry-run checks it by making and removing it.
        out = os.path.join(self.work.name, f"never-written-{next(self.runs)}")
        command = [self.granshock, "run", self.scenes[scene], "--dry-run", "--force", "--out",
                   out]
        for s in sets:
            command += ["--set", s]
        p = subprocess.run(command, capture_output=True, text=True, timeout=60,
                           env=dict(os.environ, OMP_NUM_THREADS="1", GRANSHOCK_FIGURES="0"))
        return p.returncode, p.stdout, p.stderr.strip()

    def check(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed.append(what)

    def skip(self, key, which, why):
        self.skips.append(f"skipped: {key}: {which}: {why}")


def table_rows(source):
    """The rows of docs/scene_keys.md's "Keys" table as dicts by the header's names."""
    lines = (source / "docs" / "scene_keys.md").read_text().splitlines()
    in_keys, header, rows = False, None, []
    for line in lines:
        if line.startswith("## "):
            in_keys = line == "## Keys"
        if not in_keys or not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if header is None:
            header = cells
        elif not set(line) <= set("|-: "):
            rows.append(dict(zip(header, cells)))
    return rows


def key_of(row):
    return row["key"].strip("`")


def code(cell):
    """The cell's text when it is one `code span` and nothing else; else None."""
    m = re.fullmatch(r"`([^`]+)`", cell.strip())
    return m.group(1) if m else None


def first_code(cell):
    m = re.match(r"\s*`([^`]+)`", cell)
    return m.group(1) if m else None


def flatten(resolved):
    """Resolved scene keys by dotted name; lists of tables by index."""
    out = {}

    def walk(prefix, node):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(f"{prefix}.{k}" if prefix else k, v)
        elif isinstance(node, list) and node and isinstance(node[0], dict):
            for i, v in enumerate(node):
                walk(f"{prefix}.{i}", v)
        else:
            out[prefix] = node
    walk("", resolved)
    return out


def evaluate(text, env):
    """A default or a range end: a TOML literal, a length "N d" / "N m", or an expression of
    resolved keys (dotted names), d_max and numbers."""
    try:
        value = tomllib.loads("v = " + text)["v"]
    except tomllib.TOMLDecodeError:
        value = None
    if isinstance(value, str):
        m = re.fullmatch(rf"\s*({NUMBER})\s*(d|m)\s*", value)
        if m:
            return float(m.group(1)) * (env["units.d"] if m.group(2) == "d" else 1.0)
        return value
    if value is not None:
        return value
    names = {}

    def name(m):
        key = m.group(0)
        if key not in env:
            raise KeyError(key)
        names[f"_{len(names)}"] = env[key]
        return f"_{len(names) - 1}"
    expression = re.sub(r"(?<![\w.])[a-z_]+(?:\.[a-z_]+)+", name, text)
    expression = re.sub(rf"({NUMBER})\s+d_max", r"\1 * d_max", expression)
    if not re.fullmatch(r"[\w\s.*/+\-()\[\],]*", expression):
        raise ValueError(text)
    return eval(expression, {"__builtins__": {}}, dict(names, d_max=env["d_max"]))


def same(a, b):
    if isinstance(a, list) or isinstance(b, list):
        return (isinstance(a, list) and isinstance(b, list) and len(a) == len(b)
                and all(same(x, y) for x, y in zip(a, b)))
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-300)
    return a == b


def resolved_values(key, flat):
    """The resolved values a documented key stands for (every pair of a pair key)."""
    if key.startswith('contact.pairs."a-b".'):
        field = key.rsplit(".", 1)[1]
        return [v for k, v in flat.items()
                if k.startswith("contact.pairs.") and k.endswith("." + field)]
    return [flat[key]] if key in flat else []


def check_defaults(c, rows, env, flat):
    for row in rows:
        key, default = key_of(row), row["default"]
        text = code(default)
        if text is None:
            if default.startswith("required") or default.startswith("one of"):
                continue  # no default to compare
            c.check(False, f"{key}: default {default!r} is neither `code` nor required")
            continue
        if (key, "default") in SKIPPED:
            c.skip(key, "default", SKIPPED[key, "default"])
            continue
        try:
            expected = evaluate(text, env)
        except (KeyError, ValueError, SyntaxError, NameError, TypeError) as e:
            c.check(False, f"{key}: default `{text}` cannot be evaluated ({e!r})")
            continue
        if key in NOT_WRITTEN:
            scene = NOT_WRITTEN[key]
            plain = c.dry_run(scene)
            given = c.dry_run(scene, [f"{key}={text}"])
            c.check(plain[0] == 0 and given == plain,
                    f"{key}: --set {key}={text} (the documented default) changes the dry run: "
                    f"{given[2] or 'the resolved scene differs'}")
            continue
        if key in DEFAULT_IN:
            rc, out, err = c.dry_run(DEFAULT_IN[key])
            found = resolved_values(key, flatten(tomllib.loads(out))) if rc == 0 else []
        else:
            found = resolved_values(key, flat)
        c.check(bool(found) and all(same(expected, v) for v in found),
                f"{key}: documented default `{text}` = {expected!r}, the program resolves "
                f"{found if found else 'nothing under this key'}")


def bounds(accepted, env):
    """The numeric range the "accepted" cell starts with: [(end, closed, side), ...]."""
    text = first_code(accepted)
    if text is None:
        return None
    m = re.fullmatch(r"([\[(])\s*([^,]+?)\s*,\s*([^,]+?)\s*([\])])", text)
    if m:
        return [(evaluate(m.group(2), env), m.group(1) == "[", "lower"),
                (evaluate(m.group(3), env), m.group(4) == "]", "upper")]
    m = re.fullmatch(r"(>=|>)\s*(.+)", text)
    if m:
        return [(evaluate(m.group(2), env), m.group(1) == ">=", "lower")]
    return None


def range_cases(rows, env):
    """(key, which, --set path, scene, value, extra sets, accepted?) for every range end."""
    for row in rows:
        key = key_of(row)
        try:
            ends = bounds(row["accepted"], env)
        except (KeyError, ValueError, SyntaxError, NameError, TypeError) as e:
            yield key, "range", None, None, None, [], repr(e)
            continue
        if not ends:
            continue
        path, scene = SET_AS.get(key, (key, "base"))
        integer = row["type"] == "integer"
        for end, closed, side in ends:
            if (key, side) in SKIPPED:
                yield key, side, None, None, None, [], None
                continue
            if integer:
                outside, inside = (end - 1, end + 1) if side == "lower" else (end + 1, end - 1)
            else:
                step = abs(end) * 1e-9 if end != 0 else 1e-9
                outside, inside = ((end - step, end + step) if side == "lower"
                                   else (end + step, end - step))
            checks = [(end, closed), (outside, False)]
            if not closed and (key, side + " inside") in SKIPPED:
                yield key, side + " inside", None, None, None, [], None
            elif not closed:
                checks.append((inside, True))
            for value, accepted in checks:
                scene_here, extra = scene, []
                if key in CONTEXT:
                    scene_here, extra = CONTEXT[key](value, end)
                yield key, side, path, scene_here, value, extra, accepted


def literal(value, integer):
    return str(int(value)) if integer else repr(float(value))


def check_ranges(c, rows, env):
    cases = list(range_cases(rows, env))
    types = {key_of(r): r["type"] for r in rows}
    jobs = []
    for key, which, path, scene, value, extra, accepted in cases:
        if path is None and isinstance(accepted, str):
            c.check(False, f"{key}: its range cannot be read ({accepted})")
        elif path is None:
            c.skip(key, which, SKIPPED[key, which])
        else:
            jobs.append((key, which, path, scene, value, extra, accepted))

    def run(job):
        key, which, path, scene, value, extra, accepted = job
        text = literal(value, types[key] == "integer")
        return job, text, c.dry_run(scene, extra + [f"{path}={text}"])

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for (key, which, path, scene, value, extra, accepted), text, (rc, _, err) in \
                pool.map(run, jobs):
            given = " ".join(f"--set {s}" for s in extra + [f"{path}={text}"])
            if accepted:
                c.check(rc == 0, f"{key}: {which} end: {given} should be accepted, "
                                 f"exit {rc}: {err}")
            else:
                c.check(rc == 2 and f"'{path}'" in err,
                        f"{key}: {which} end: {given} should be refused naming '{path}', "
                        f"exit {rc}: {err or '(accepted)'}")


def check_choices(c, rows):
    jobs = []
    for row in rows:
        key = key_of(row)
        if row["type"] != "string":
            continue
        if not re.fullmatch(r"[a-z_]+(?:, [a-z_]+)+", row["accepted"]):
            continue  # not a list of names alone
        names = row["accepted"].split(", ")
        if (key, "choices") in SKIPPED:
            c.skip(key, "choices", SKIPPED[key, "choices"])
            continue
        path, scene = SET_AS.get(key, (key, "base"))
        for name in names:
            jobs.append((key, path, CHOICE_SCENE.get((key, name), scene), name, True))
        jobs.append((key, path, scene, "not_a_" + names[0], False))

    def run(job):
        key, path, scene, name, accepted = job
        return job, c.dry_run(scene, [f'{path}="{name}"'])

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for (key, path, scene, name, accepted), (rc, _, err) in pool.map(run, jobs):
            if accepted:
                c.check(rc == 0, f'{key}: --set {path}="{name}" should be accepted, exit {rc}: '
                                 f"{err}")
            else:
                c.check(rc == 2 and f"'{path}'" in err,
                        f'{key}: --set {path}="{name}" should be refused naming the key, exit '
                        f"{rc}: {err or '(accepted)'}")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    c = Checker(sys.argv[1], sys.argv[2])
    rows = table_rows(c.source)
    c.check(len(rows) > 40, f"docs/scene_keys.md: {len(rows)} rows in the Keys table")
    rc, out, err = c.dry_run("base")
    if rc != 0:
        print(f"FAIL: the base scene is refused: {err}")
        print("0 passed, 1 failed")
        return 1
    resolved = tomllib.loads(out)
    flat = flatten(resolved)
    env = dict(flat, d_max=max(s["diameter"] for s in resolved["species"]))
    check_defaults(c, rows, env, flat)
    check_ranges(c, rows, env)
    check_choices(c, rows)
    for line in c.skips:
        print(line)
    for line in c.failed:
        print("FAIL:", line)
    print(f"{c.passed} passed, {len(c.failed)} failed")
    return 1 if c.failed else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Checks the lines the field figures of plot_fields.py draw (docs/fields.md, "figures/"),
reading them back from the matplotlib figures, drawn once without writing them:

- each shock front (the artists whose gid names its /lines dataset, shock_temperature or
  shock_threshold; a line without one is matched to the front whose columns hold all its
  vertices) runs only through the columns where the analysis found that front
  (/front/y_temperature, /front/y_threshold finite), from each such column only to the
  next, at the analysis' y: no segment spans a column without that front; and it draws
  every run of two or more such columns, each apart (a column without a front breaks the
  line; a lone column draws nothing);
- the sonic line draws the polylines of /lines/sonic, each apart;
- every set of lines drawn has its legend entry (the phi half-way front's included), and
  a front that is not drawn has none;
- mach.png and solid_fraction.png draw both fronts wherever they have a run to draw;
  temperature.png is held to the same rules for any line it draws.

First on the fields.h5 of a short run of apps/bench/lammps/small_bow_shock.toml (about
1.5 s on 2 cores; its phi front has gaps), then on copies of it whose fronts are replaced
by made-up ones: gaps and lone columns, the phi front's first polyline a single column
(its legend entry went missing when only a set's first polyline was labelled and that one
was too short to draw), a phi front of lone columns only (nothing drawn, no entry).
Prints PASS or FAIL lines.

Usage: check_figure_fronts.py GRANSHOCK SOURCE_DIR
"""
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

FRONTS = {"shock_temperature": "y_temperature", "shock_threshold": "y_threshold"}
FIELD_FIGURES = ("mach.png", "solid_fraction.png", "temperature.png")
FRONT_FIGURES = ("mach.png", "solid_fraction.png")  # the figures that draw the fronts


class Captured:
    """Stands for figure_files.FigureDirectory: keeps each figure instead of writing it."""

    def __init__(self):
        self.figures = {}

    def save(self, fig, name, **_):
        self.figures[name] = fig


def pieces(xy):
    """The parts of a drawn line between NaN vertices (where matplotlib breaks it)."""
    finite = np.all(np.isfinite(xy), axis=1)
    parts, current = [], []
    for point, ok in zip(xy, finite):
        if ok:
            current.append(point)
        elif current:
            parts.append(np.array(current))
            current = []
    if current:
        parts.append(np.array(current))
    return parts


def runs(y):
    """Index ranges [begin, end) of consecutive finite values of y."""
    found, begin = [], None
    for i, v in enumerate(list(y) + [np.nan]):
        if np.isfinite(v) and begin is None:
            begin = i
        elif not np.isfinite(v) and begin is not None:
            found.append((begin, i))
            begin = None
    return found


def stored(fields_h5):
    """Per column x and each front's y (NaN: no front there), and the sonic polylines, in d."""
    with h5py.File(fields_h5, "r") as f:
        d = float(f.attrs["d"])
        x = f["front/x"][...] / d
        fronts = {gid: f["front/" + name][...] / d for gid, name in FRONTS.items()
                  if "front/" + name in f}
        sonic = []
        if "lines/sonic" in f:
            points, offsets = f["lines/sonic/points"][...] / d, f["lines/sonic/offsets"][...]
            sonic = [points[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]
    return x, fronts, sonic


def check_front(name, gid, parts, x, y):
    """Failures of the pieces drawn for one front against its per-column y."""
    failures = []
    spacing = np.min(np.diff(x)) if len(x) > 1 else 1.0
    drawn = []
    for part in parts:
        columns = []
        for px, py in part:
            i = int(np.argmin(np.abs(x - px)))
            if abs(x[i] - px) > 1e-6 * spacing:
                failures.append(f"{name}: {gid} has a vertex at x = {px:.4g} d, no column centre")
            elif not np.isfinite(y[i]):
                failures.append(f"{name}: {gid} has a vertex at x = {px:.4g} d, a column "
                                "without that front")
            elif not np.isclose(py, y[i], rtol=1e-9, atol=1e-9):
                failures.append(f"{name}: {gid} at x = {px:.4g} d is drawn at y = {py:.4g} d, "
                                f"the analysis has {y[i]:.4g} d")
            columns.append(i)
        for a, b in zip(columns, columns[1:]):
            if b != a + 1:
                failures.append(f"{name}: {gid} has a segment from x = {x[a]:.4g} d to "
                                f"{x[b]:.4g} d, across {abs(b - a) - 1} column(s) "
                                "(without that front)" if abs(b - a) > 1 else
                                f"{name}: {gid} has a segment from x = {x[a]:.4g} d back or "
                                f"onto itself ({x[b]:.4g} d)")
        if len(columns) > 1:
            drawn.append((columns[0], columns[-1] + 1))
    expected = [r for r in runs(y) if r[1] - r[0] > 1]
    if sorted(drawn) != expected:
        failures.append(f"{name}: {gid} draws the column runs {sorted(drawn)}, the analysis "
                        f"found {expected} (index ranges of two or more columns)")
    return failures


def check_sonic(name, parts, sonic):
    expected = [line for line in sonic if len(line) > 1]
    if len(parts) != len(expected) or not all(
            p.shape == e.shape and np.allclose(p, e) for p, e in zip(parts, expected)):
        return [f"{name}: the sonic line draws {len(parts)} line(s), not the {len(expected)} "
                "polylines of /lines/sonic each apart"]
    return []


def on_columns(parts, x, y):
    """Whether every vertex of parts lies on a column centre where y has that front."""
    spacing = np.min(np.diff(x)) if len(x) > 1 else 1.0
    for part in parts:
        for px, py in part:
            i = int(np.argmin(np.abs(x - px)))
            if abs(x[i] - px) > 1e-6 * spacing or not np.isclose(py, y[i], rtol=1e-9, atol=1e-9):
                return False
    return True


def identify(line, parts, x, fronts, sonic):
    """Which set a drawn line belongs to: its gid where that names one (plot_fields.py
    sets it), else the one front whose columns hold all its vertices, else the sonic line
    when its vertices are those of /lines/sonic; None when none fits."""
    gid = line.get_gid()
    if gid in fronts or gid == "sonic":
        return gid
    matching = [g for g, y in fronts.items() if on_columns(parts, x, y)]
    if len(matching) == 1:
        return matching[0]
    if sonic:
        known = np.concatenate(sonic)
        if all(np.any(np.all(np.isclose(known, v), axis=1)) for p in parts for v in p):
            return "sonic"
    return None


def check(fields_h5, plot_fields, what):
    x, fronts, sonic = stored(fields_h5)
    out = Captured()
    plot_fields.draw_figures(plot_fields.Run(fields_h5), out)
    failures = []
    for name in FIELD_FIGURES:
        ax = out.figures[name].axes[0]
        legend = ax.get_legend()
        texts = [t.get_text() for t in legend.get_texts()] if legend else []
        drawn, named = {}, {}  # per set: the pieces drawn, whether an artist has its entry
        for line in ax.get_lines():
            parts = [p for p in pieces(np.asarray(line.get_xydata(), dtype=float)) if len(p) > 1]
            if not parts:
                continue  # nothing visible
            which = identify(line, parts, x, fronts, sonic)
            if which is None:
                failures.append(f"{name}: a line (label {line.get_label()!r}) that is neither "
                                "a front of /front nor the sonic line")
                continue
            drawn.setdefault(which, []).extend(parts)
            named[which] = named.get(which, False) or line.get_label() in texts
        for which, parts in drawn.items():
            if not named[which]:
                failures.append(f"{name}: {which} is drawn without its legend entry: {texts}")
            if which in fronts:
                failures += check_front(name, which, parts, x, fronts[which])
            else:
                failures += check_sonic(name, parts, sonic)
        if name in FRONT_FIGURES:
            for gid, y in fronts.items():
                if gid not in drawn and any(e - b > 1 for b, e in runs(y)):
                    failures.append(f"{name}: {gid} has runs of columns with a front but is "
                                    "not drawn")
            if name == "mach.png" and "sonic" not in drawn and any(len(s) > 1 for s in sonic):
                failures.append(f"{name}: the sonic line is not drawn")
            if "shock_threshold" not in drawn and any("half-way" in t for t in texts):
                failures.append(f"{name}: a legend entry for the phi half-way front, which is "
                                f"not drawn: {texts}")
    plt.close("all")
    for message in failures:
        print(f"FAIL {what}: {message}", file=sys.stderr)
    print(f"{what}: {'FAIL' if failures else 'ok'}: fronts drawn through the column runs "
          + ", ".join(f"{gid} {[r for r in runs(y) if r[1] - r[0] > 1]}"
                      for gid, y in fronts.items()))
    return failures


def replace_fronts(source, target, fronts):
    """A copy of fields.h5 whose /front/y_* and /lines/shock_* are the made-up per-column
    fronts (in units of the column spacing above the grid's first row), the lines built
    from them as the analysis builds them (consecutive columns with a front)."""
    shutil.copyfile(source, target)
    with h5py.File(target, "r+") as f:
        x = f["front/x"][...]
        y0, dy = float(f["grid/y_nodes"][0]), float(f["grid/y_nodes"][1] - f["grid/y_nodes"][0])
        for gid, rows in fronts.items():
            y = np.array([y0 + r * dy if r is not None else np.nan for r in rows], dtype=float)
            assert y.size == x.size, "a made-up front needs one value per column"
            name = FRONTS[gid]
            del f["front/" + name]
            f["front/" + name] = y
            points = [[x[i], y[i]] for b, e in runs(y) for i in range(b, e)]
            offsets = [0]
            for b, e in runs(y):
                offsets.append(offsets[-1] + e - b)
            del f["lines/" + gid]
            f["lines/" + gid + "/points"] = np.array(points, dtype=float).reshape(-1, 2)
            f["lines/" + gid + "/offsets"] = np.array(offsets, dtype=np.int64)


def main():
    granshock, src = sys.argv[1], sys.argv[2]
    sys.path.insert(0, os.path.join(src, "analysis"))
    import plot_fields  # noqa: E402

    scene = os.path.join(src, "apps/bench/lammps/small_bow_shock.toml")
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        r = subprocess.run([granshock, "run", scene, "--out", f"{tmp}/run", "--quiet",
                            "--no-figures", "--set", "time.duration=0.03",
                            "--set", "time.production_start=0.02"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            print(f"FAIL: granshock run exited {r.returncode}: {r.stderr.strip()}")
            return 1
        fields_h5 = f"{tmp}/run/fields.h5"
        failures += check(fields_h5, plot_fields, "short run")
        with h5py.File(fields_h5, "r") as f:
            nx = f["front/x"].size
        if nx < 8:
            print(f"FAIL: the run's grid has {nx} columns, the made-up fronts need 8")
            return 1
        # Rows of each column's front (None: no front there), padded to the grid's columns.
        lone_first = [3, None, 4, 5, 6, None, None, 7] + [None] * (nx - 8)
        gaps = [None, 2, 3, None, 5, 4, 6, 8] + [2, None] * ((nx - 8) // 2) + [None] * (nx % 2)
        lone_only = [3, None, 4, None, None, 6, None, 7] + [None] * (nx - 8)
        cases = {
            "phi front's first line one column": {"shock_threshold": lone_first,
                                                  "shock_temperature": gaps},
            "fronts with gaps": {"shock_threshold": gaps, "shock_temperature": lone_first},
            "phi front of lone columns only": {"shock_threshold": lone_only,
                                               "shock_temperature": gaps},
        }
        for i, (what, fronts) in enumerate(cases.items()):
            target = f"{tmp}/made_up_{i}.h5"
            replace_fronts(fields_h5, target, fronts)
            failures += check(target, plot_fields, what)
    print("FAIL" if failures else "PASS")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

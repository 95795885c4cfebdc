#!/usr/bin/python3
"""The Python reader (python/granshock, docs/python.md) against files granshock writes.

Makes tiny runs with the built program (a cylinder whose front is found, a wedge with
friction, a plate), a fields directory (`fields RUN --out DIR`) and one case of the tiny
study with its table (`study tests/study/tiny.toml --case 0`, then `--collect`), then
checks what the reader gives against what h5py, json and csv read from the same files,
and runs the import line and the ```python blocks of docs/python.md verbatim.

Usage: test_reader.py GRANSHOCK SOURCE_DIR [unittest options]
"""
import contextlib
import csv
import json
import io
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import h5py
import numpy as np

GRANSHOCK = SOURCE = WORK = None
granshock = None  # imported from SOURCE/python in main()

# The tiny study's channel (tests/study/tiny.toml: 40 d x 60 d, a cylinder of 10 d), with a
# snapshot every 1 ms so that the particle count differs between frames (padding to trim).
CHANNEL = ["domain.width=40 d", "domain.length=60 d", 'obstacle.centre=["20 d", "35 d"]',
           "output.sample_every=20", "output.snapshot_interval=0.001",
           "output.checkpoint_interval=0.002", "output.series_interval=0.0005",
           "output.progress_interval=1000"]
# 8 ms, fields from 4 ms: the shortest run of this channel whose primary front is found,
# so that delta/D is a number to compare (about a second on one thread).
CYLINDER = CHANNEL + ["obstacle.diameter=10 d", "time.duration=0.008",
                      "time.production_start=0.004"]
# 4 ms with friction: snapshots with angular_velocity.
WEDGE = CHANNEL + ["obstacle.length=12 d", "obstacle.half_angle=25", "contact.friction=0.3",
                   "time.duration=0.004", "time.production_start=0.002"]
PLATE = CHANNEL + ["obstacle.width=10 d", "time.duration=0.004", "time.production_start=0.002"]
# A square turned by 30 degrees: its outline in fields.h5 (format 2) is what granshock met.
SQUARE = CHANNEL + ["obstacle.side=8 d", "obstacle.rotation=30", "time.duration=0.004",
                    "time.production_start=0.002"]
TINY_CASES = ["phi-0.1_e-0.5", "phi-0.1_e-0.8", "phi-0.12_e-0.5", "phi-0.12_e-0.8"]


def granshock_command(*args, codes=(0,)):
    """Runs the program in WORK without figures; fails with its stderr on another code."""
    env = dict(os.environ, GRANSHOCK_FIGURES="0")
    env.setdefault("OMP_NUM_THREADS", "1")
    p = subprocess.run([GRANSHOCK, *args], cwd=WORK, env=env, capture_output=True, text=True)
    if p.returncode not in codes:
        raise RuntimeError(f"granshock {' '.join(args)}: exit code {p.returncode}\n{p.stderr}")


def run_scene(scene, out, settings):
    args = ["run", str(SOURCE / "scenes" / scene), "--out", out, "--quiet", "--no-figures"]
    for setting in settings:
        args += ["--set", setting]
    granshock_command(*args)


def make_outputs():
    """The run, fields and study directories of the tests, under WORK/runs."""
    run_scene("default.toml", "runs/default", CYLINDER)
    granshock_command("fields", "runs/default", "--out", "runs/default_fields", "--no-figures")
    run_scene("wedge.toml", "runs/wedge", WEDGE)
    run_scene("plate.toml", "runs/plate", PLATE)
    run_scene("square.toml", "runs/square", SQUARE)
    study = str(SOURCE / "tests" / "study" / "tiny.toml")  # writes runs/tiny
    granshock_command("study", study, "--case", "0", "--quiet", "--no-figures")
    # --collect ends with 1 while cases are missing; the table is written all the same.
    granshock_command("study", study, "--collect", "--quiet", "--no-figures", codes=(0, 1))


def runs(name):
    return WORK / "runs" / name


def same_number(a, b, rel=1e-12):
    """Equal numbers, or both undetermined (None in JSON, NaN in HDF5)."""
    a = math.nan if a is None else float(a)
    b = math.nan if b is None else float(b)
    return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=rel, abs_tol=0)


class Snapshots(unittest.TestCase):
    def check_run(self, name, expect_spin):
        run = granshock.open_run(runs(name))
        with h5py.File(runs(name) / "run.h5", "r") as f:
            group = f["particles/all"]
            counts = group["count/value"][()]
            n_max = group["id/value"].shape[1]
            elements = sorted(k for k in group if k not in ("box", "count"))
            self.assertEqual(len(run.times), len(counts))
            self.assertTrue(np.array_equal(run.times, group["count/time"][()]))
            self.assertTrue(np.array_equal(run.steps, group["count/step"][()]))
            self.assertGreater(len(set(counts)), 1, "the frames' counts should differ")
            self.assertLess(counts.min(), n_max, "some frame should be padded")
            reordered = 0
            for i, n in enumerate(counts):
                snapshot = run.snapshot(i)
                self.assertEqual(sorted(snapshot), elements)
                self.assertEqual((snapshot.count, snapshot.index), (n, i))
                self.assertEqual(snapshot.time, group["count/time"][i])
                ids = group["id/value"][i, :n]
                order = np.argsort(ids)
                reordered += not np.array_equal(order, np.arange(n))
                for element in elements:
                    direct = group[element + "/value"][i, :n][order]
                    self.assertTrue(np.array_equal(snapshot[element], direct), (i, element))
                    self.assertEqual(len(snapshot[element]), n)
                self.assertTrue(np.all(np.diff(snapshot["id"]) > 0), "sorted by unique ids")
                self.assertFalse(np.isnan(snapshot["position"]).any(), "padding trimmed")
                self.assertTrue((snapshot["species"] >= 0).all(), "padding trimmed")
            self.assertGreater(reordered, 0, "the solver's order is not the ids'")
        self.assertEqual("angular_velocity" in run.snapshot(0), expect_spin)
        last = run.snapshot(-1)
        self.assertEqual(last.index, len(counts) - 1)
        with self.assertRaises(IndexError):
            run.snapshot(len(counts))
        return run

    def test_cylinder_snapshots_equal_the_trimmed_sorted_datasets(self):
        self.check_run("default", expect_spin=False)

    def test_friction_snapshots_carry_angular_velocity(self):
        self.check_run("wedge", expect_spin=True)

    def test_dataframe_has_one_row_per_particle(self):
        snapshot = granshock.open_run(runs("wedge")).snapshot(1)
        frame = snapshot.to_dataframe()
        self.assertEqual(list(frame.index), list(snapshot["id"]))
        self.assertEqual(list(frame.columns),
                         ["x", "y", "vx", "vy", "angular_velocity", "species", "radius"])
        self.assertTrue(np.array_equal(frame["vy"], snapshot["velocity"][:, 1]))


class Observables(unittest.TestCase):
    def test_one_row_per_time_series_row(self):
        run = granshock.open_run(runs("default"))
        table = run.observables
        with h5py.File(runs("default") / "run.h5", "r") as f:
            group = f["observables"]
            rows = len(group["particles/step"])
            self.assertEqual(len(table), rows)
            self.assertEqual(sorted(table.columns), sorted(["time", *group]))
            self.assertTrue(np.array_equal(table.index, group["particles/step"][()]))
            self.assertTrue(np.array_equal(table["time"], group["particles/time"][()]))
            for name in group:
                self.assertTrue(np.array_equal(table[name], group[name + "/value"][()]), name)
        # A row every series_interval from 0 to the end: 0.008 s / 0.0005 s + 1.
        duration, interval = run.scene["time"]["duration"], run.scene["output"]["series_interval"]
        self.assertEqual(rows, round(duration / interval) + 1)
        self.assertEqual(table.attrs["units"]["kinetic_energy"], "J")


class Thermo(unittest.TestCase):
    def test_the_thermo_table_ends_at_the_runs_last_step(self):
        run = granshock.open_run(runs("default"))
        table = run.thermo
        self.assertEqual(list(table.columns)[:3], ["Step", "Time", "Particles"])
        self.assertEqual(table["Step"].iloc[-1], run.summary["steps"])
        self.assertEqual(table["Particles"].iloc[-1], run.observables["particles"].iloc[-1])


class Scene(unittest.TestCase):
    def test_resolved_scene_is_the_stored_toml(self):
        run = granshock.open_run(runs("default"))
        self.assertEqual(run.scene["obstacle"]["diameter"], 0.01)  # "10 d", d = 1 mm
        self.assertEqual(run.scene["time"]["duration"], 0.008)
        self.assertEqual(run.species, [s["name"] for s in run.scene["species"]])
        self.assertEqual(run.summary["steps"], round(0.008 / run.scene["time"]["dt"]))


class Fields(unittest.TestCase):
    def test_every_field_has_the_grid_shape(self):
        run = granshock.open_run(runs("default"))
        fields = run.fields
        with h5py.File(runs("default") / "fields.h5", "r") as f:
            nx, ny = int(f["grid"].attrs["nx"]), int(f["grid"].attrs["ny"])
            self.assertEqual(sorted(fields), sorted(f["fields"]))
            for name, values in fields.items():
                self.assertEqual(values.shape, (ny, nx), name)
                self.assertTrue(np.array_equal(values, f["fields/" + name][()], equal_nan=True))
        self.assertEqual(nx * ny, run.summary["fields_bins"])
        self.assertEqual(int(fields["masked"].sum()), run.summary["fields_masked_bins"])
        grid = fields.grid
        self.assertTrue(np.allclose(fields.x, grid["x0"] + (np.arange(nx) + 0.5) * grid["dx"]))
        self.assertTrue(np.allclose(fields.y, grid["y0"] + (np.arange(ny) + 0.5) * grid["dy"]))
        self.assertEqual((len(fields.x_nodes), len(fields.y_nodes)), (nx + 1, ny + 1))
        # The columns tile the periodic width (docs/fields.md, section 1).
        self.assertAlmostEqual(nx * grid["dx"], run.scene["domain"]["width"], places=12)
        self.assertEqual(len(fields.to_dataframe()), nx * ny)
        self.assertEqual(fields.units["T"], "J")


class Fronts(unittest.TestCase):
    def test_summary_delta_equals_the_stored_fronts(self):
        run = granshock.open_run(runs("default"))
        fronts, summary = run.fronts, run.summary
        self.assertIsNotNone(summary["delta_over_D"], "the test run should find its front")
        self.assertEqual(fronts.primary_definition, summary["delta_definition"])
        self.assertTrue(same_number(fronts.delta_over_D, summary["delta_over_D"]))
        self.assertTrue(same_number(fronts.delta_over_D_err, summary["delta_over_D_err"]))
        self.assertTrue(same_number(fronts.profile["delta"], summary["detachment_length_m"]))
        self.assertEqual(sorted(fronts.definitions.index), sorted(summary["detachment"]))
        for name, result in summary["detachment"].items():
            row = fronts.definitions.loc[name]
            self.assertTrue(same_number(row["delta_over_D"], result["delta_over_D"]), name)
            self.assertTrue(same_number(row["delta_over_D_err"], result["delta_over_D_err"]), name)
        primary = fronts.definitions.loc[fronts.primary_definition]
        self.assertTrue(same_number(primary["delta_over_D"], fronts.delta_over_D))
        self.assertTrue(same_number(fronts.shock_angle["angle_deg"], summary["shock_angle_deg"]))
        self.assertTrue(same_number(fronts.upstream["inlet"]["Ma"], summary["ma_inf_measured"]))
        self.assertTrue(same_number(fronts.upstream["downstream"]["Ma"],
                                    summary["ma_inf_measured_downstream"]))

    def test_profile_columns_and_lines_are_the_stored_arrays(self):
        run = granshock.open_run(runs("default"))
        fronts = run.fronts
        with h5py.File(runs("default") / "fields.h5", "r") as f:
            self.assertEqual(len(fronts.stagnation_line), len(f["profile/y"]))
            self.assertTrue(np.array_equal(fronts.stagnation_line["phi"], f["profile/phi"][()],
                                           equal_nan=True))
            self.assertEqual(len(fronts.columns), int(f["grid"].attrs["nx"]))
            self.assertTrue(np.array_equal(fronts.columns["y_temperature"],
                                           f["front/y_temperature"][()], equal_nan=True))
            self.assertEqual(len(fronts.delta_blocks), run.scene["output"]["blocks"])
            self.assertEqual(sorted(fronts.lines), sorted(f["lines"]))
            for name, lines in fronts.lines.items():
                points = np.concatenate(lines) if lines else np.zeros((0, 2))
                self.assertTrue(np.array_equal(points, f[f"lines/{name}/points"][()]), name)


class Obstacles(unittest.TestCase):
    def fields_geometry(self, name):
        with h5py.File(runs(name) / "fields.h5", "r") as f:
            return {k: f.attrs[k] for k in ("obstacle_width", "obstacle_face", "obstacle_back")}

    def check_against_fields(self, name):
        """The scene's obstacle where the analysis has it, and the fields directory's
        reconstruction from fields.h5 the same."""
        obstacle = granshock.open_run(runs(name)).obstacle
        stored = self.fields_geometry(name)
        self.assertAlmostEqual(obstacle.frontal_width, stored["obstacle_width"], places=12)
        self.assertAlmostEqual(obstacle.face, stored["obstacle_face"], places=12)
        self.assertAlmostEqual(obstacle.back, stored["obstacle_back"], places=12)
        self.assertTrue(np.array_equal(obstacle.outline[0], obstacle.outline[-1]), "closed")
        return obstacle

    def test_cylinder_outline_has_the_scene_diameter(self):
        run = granshock.open_run(runs("default"))
        obstacle = self.check_against_fields("default")
        diameter = run.scene["obstacle"]["diameter"]
        x, y = obstacle.outline.T
        self.assertEqual(obstacle.shape, "cylinder")
        self.assertAlmostEqual(x.max() - x.min(), diameter, places=12)
        self.assertAlmostEqual(y.max() - y.min(), diameter, places=12)
        radii = np.hypot(x - obstacle.centre[0], y - obstacle.centre[1])
        self.assertTrue(np.allclose(radii, diameter / 2, rtol=1e-12))
        self.assertEqual(list(obstacle.centre), run.scene["obstacle"]["centre"])

    def test_wedge_outline_is_its_triangle(self):
        run = granshock.open_run(runs("wedge"))
        obstacle = self.check_against_fields("wedge")
        scene = run.scene["obstacle"]
        xc, yc = scene["centre"]
        half_length = scene["length"] / 2
        half_base = scene["length"] * math.tan(math.radians(scene["half_angle"]))
        # The tip upstream on the axis, then the base's corners, counter-clockwise.
        triangle = [[xc, yc - half_length], [xc + half_base, yc + half_length],
                    [xc - half_base, yc + half_length]]
        self.assertTrue(np.allclose(obstacle.outline[:3], triangle, rtol=1e-12))
        self.assertEqual(len(obstacle.outline), 4)

    def test_plate_outline_is_its_rectangle(self):
        run = granshock.open_run(runs("plate"))
        obstacle = self.check_against_fields("plate")
        scene = run.scene["obstacle"]
        x, y = obstacle.outline.T
        self.assertAlmostEqual(x.max() - x.min(), scene["width"], places=12)
        self.assertAlmostEqual(y.max() - y.min(), scene["thickness"], places=12)
        self.assertEqual(len(obstacle.outline), 5)

    def test_square_outline_is_the_one_granshock_met(self):
        run = granshock.open_run(runs("square"))
        obstacle = self.check_against_fields("square")
        scene = run.scene["obstacle"]
        with h5py.File(runs("square") / "fields.h5", "r") as f:
            self.assertEqual(int(f.attrs["granshock_format_version"]), 2)
            stored = f["obstacle/outline"][...]
        # The scene's corners (python/granshock/obstacle.py) are the file's, in order.
        self.assertTrue(np.allclose(obstacle.outline[:4], stored, rtol=1e-12, atol=0))
        side, turn = scene["side"], math.radians(scene["rotation"])
        x, y = stored.T
        across = side * (math.cos(turn) + math.sin(turn))
        self.assertAlmostEqual(x.max() - x.min(), across, places=12)
        self.assertAlmostEqual(obstacle.frontal_width, across, places=12)


class FieldsDirectory(unittest.TestCase):
    def test_fields_directory_reads_like_its_run(self):
        analysis = granshock.open_run(runs("default_fields"))
        run = granshock.open_run(runs("default"))
        self.assertEqual((analysis.kind, run.kind), ("fields", "run"))
        self.assertEqual(analysis.species, run.species)
        self.assertTrue(same_number(analysis.summary["delta_over_D"], run.summary["delta_over_D"]))
        self.assertEqual(sorted(analysis.fields), sorted(run.fields))
        for name in run.fields:
            self.assertTrue(np.array_equal(analysis.fields[name], run.fields[name], equal_nan=True))
        self.assertTrue(same_number(analysis.fronts.delta_over_D, run.fronts.delta_over_D))
        self.assertEqual(analysis.obstacle.shape, run.obstacle.shape)
        self.assertTrue(np.allclose(analysis.obstacle.outline, run.obstacle.outline, rtol=1e-12))

    def test_run_only_attributes_raise(self):
        analysis = granshock.open_run(runs("default_fields"))
        for what in ("scene", "observables", "times", "steps"):
            with self.assertRaises(granshock.NoRunFileError) as raised:
                getattr(analysis, what)
            self.assertIn(str(runs("default_fields")), str(raised.exception))
        with self.assertRaises(granshock.NoRunFileError):
            analysis.snapshot(0)
        self.assertTrue(issubclass(granshock.NoRunFileError, ValueError))


class Study(unittest.TestCase):
    def test_table_is_the_study_table(self):
        study = granshock.open_study(runs("tiny"))
        table = study.table
        self.assertEqual(study.name, "tiny")
        self.assertEqual(study.cases, TINY_CASES)
        self.assertEqual(list(table["index"]), [0, 1, 2, 3])
        self.assertEqual(list(table["status"]), ["finished", "missing", "missing", "missing"])
        with open(runs("tiny") / "study.csv", newline="") as f:
            rows = list(csv.reader(f))
        self.assertEqual(list(table.columns), rows[0])
        self.assertEqual(len(table), len(rows) - 1)
        # study.csv holds the same cells, numbers to 10 significant digits.
        for column, cell in zip(rows[0], rows[1]):
            value = table.loc[0, column]
            if value is None or (isinstance(value, float) and math.isnan(value)):
                self.assertEqual(cell, "", column)
            elif isinstance(value, (bool, np.bool_)):
                self.assertEqual(cell, "true" if value else "false", column)
            elif isinstance(value, str):
                self.assertEqual(cell, value, column)
            else:
                self.assertTrue(math.isclose(float(cell), value, rel_tol=1e-9), column)

    def test_a_record_opens_as_its_run(self):
        # The record of the finished case (docs/study.md, "Campaign records"): its summary
        # and scene the run's, its fields the run's to float32's rounding.
        record = granshock.open_run(runs("tiny") / "records" / "cases" / TINY_CASES[0])
        run = granshock.open_study(runs("tiny")).run(0)
        self.assertEqual(record.kind, "fields")
        # A record names the run directory by its case (no path of the machine: the run's
        # warnings name it as the study was given it, runs/tiny/<case>).
        text = re.sub(r'[^"\s]*/' + re.escape(TINY_CASES[0]), TINY_CASES[0],
                      json.dumps(run.summary))
        self.assertEqual(record.summary, json.loads(text))
        self.assertEqual(record.scene, run.scene)
        for name in ("phi", "T", "Ma"):
            a, b = record.fields[name], run.fields[name]
            self.assertEqual(a.dtype, np.float32)
            self.assertTrue(np.allclose(a, b, rtol=1e-6, atol=0, equal_nan=True), name)
        self.assertTrue(same_number(record.fronts.delta_over_D, run.fronts.delta_over_D))

    def test_cases_open_as_runs(self):
        study = granshock.open_study(runs("tiny"))
        first = study.run(0)
        self.assertEqual(first.path, study.run(TINY_CASES[0]).path)
        self.assertEqual(first.path, runs("tiny") / TINY_CASES[0])
        row = study.table.iloc[0]
        for key in ("ma_inf_measured", "phi_peak", "wall_seconds"):
            self.assertTrue(same_number(row[key], first.summary[key], rel=0), key)
        self.assertEqual(list(study.runs()), TINY_CASES[:1])
        with self.assertRaises(granshock.GranshockError) as raised:
            study.run(TINY_CASES[1])
        self.assertIn(TINY_CASES[1], str(raised.exception))
        with self.assertRaises(KeyError):
            study.run("no-such-case")


class Errors(unittest.TestCase):
    def expect_refusal(self, opener, path, words):
        with self.assertRaises(granshock.GranshockError) as raised:
            opener(path)
        message = str(raised.exception)
        self.assertIn(str(path), message)
        self.assertRegex(message, words)
        self.assertIsInstance(raised.exception, ValueError)

    def test_foreign_directories_are_refused_by_name(self):
        foreign = WORK / "foreign"
        foreign.mkdir(exist_ok=True)
        (foreign / "notes.txt").write_text("mine\n")
        self.expect_refusal(granshock.open_run, foreign, "not a granshock run or fields")
        self.expect_refusal(granshock.open_run, WORK / "no-such-run", "no such directory")
        self.expect_refusal(granshock.open_run, foreign / "notes.txt", "not a directory")
        self.expect_refusal(granshock.open_run, runs("tiny"), "study directory")
        self.expect_refusal(granshock.open_study, runs("default"), "not a granshock study")
        self.expect_refusal(granshock.open_study, foreign, "not a granshock study")

    def test_files_that_are_not_granshocks_are_refused_by_name(self):
        text = WORK / "text_run"
        text.mkdir(exist_ok=True)
        (text / "run.h5").write_text("not HDF5\n")
        self.expect_refusal(granshock.open_run, text, "not an HDF5 file")
        plain = WORK / "plain_hdf5"
        plain.mkdir(exist_ok=True)
        with h5py.File(plain / "run.h5", "w") as f:
            f["x"] = [1, 2, 3]
        self.expect_refusal(granshock.open_run, plain, "no granshock file")
        swapped = WORK / "fields_as_run"
        swapped.mkdir(exist_ok=True)
        shutil.copy(runs("default") / "fields.h5", swapped / "run.h5")
        self.expect_refusal(granshock.open_run, swapped, "granshock fields file, not a run file")

    def test_missing_outputs_are_named(self):
        bare = WORK / "run_h5_only"
        bare.mkdir(exist_ok=True)
        shutil.copy(runs("default") / "run.h5", bare / "run.h5")
        run = granshock.open_run(bare)
        self.assertEqual(len(run.times), len(granshock.open_run(runs("default")).times))
        for what, name in (("summary", "summary.json"), ("fields", "fields.h5"),
                           ("fronts", "fields.h5")):
            with self.assertRaises(granshock.GranshockError) as raised:
                getattr(run, what)
            self.assertIn(str(bare / name), str(raised.exception))


def fenced_blocks(markdown, language):
    return re.findall(r"^```" + language + r"\n(.*?)^```", markdown, re.S | re.M)


class Docs(unittest.TestCase):
    def test_the_documented_import_line_works(self):
        docs = (SOURCE / "docs" / "python.md").read_text()
        lines = [b for b in fenced_blocks(docs, "sh") if "import granshock" in b]
        self.assertEqual(len(lines), 1, "docs/python.md shows the import line once")
        p = subprocess.run(["bash", "-c", lines[0]], cwd=SOURCE, capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stderr)

    def test_python_blocks_run_verbatim(self):
        docs = (SOURCE / "docs" / "python.md").read_text()
        blocks = fenced_blocks(docs, "python")
        self.assertGreaterEqual(len(blocks), 3)
        namespace, printed = {}, io.StringIO()
        old = os.getcwd()
        os.chdir(WORK)  # where runs/default, runs/default_fields and runs/tiny are
        try:
            with contextlib.redirect_stdout(printed):
                for block in blocks:
                    exec(compile(block, "docs/python.md", "exec"), namespace)
        finally:
            os.chdir(old)
        self.assertIn("delta/D =", printed.getvalue())


def main():
    global GRANSHOCK, SOURCE, WORK, granshock
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    GRANSHOCK = os.path.abspath(sys.argv[1])
    SOURCE = pathlib.Path(sys.argv[2]).resolve()
    sys.path.insert(0, str(SOURCE / "python"))
    import granshock as package
    granshock = package
    WORK = pathlib.Path(tempfile.mkdtemp(prefix="granshock-python-"))
    try:
        start = time.monotonic()
        make_outputs()
        print(f"granshock's outputs written in {time.monotonic() - start:.1f} s", flush=True)
        program = unittest.main(argv=[sys.argv[0], *sys.argv[3:]], exit=False, verbosity=1)
        return 0 if program.result.wasSuccessful() else 1
    finally:
        shutil.rmtree(WORK, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())

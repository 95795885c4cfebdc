#!/usr/bin/python3
"""A granshock run's own particles, written as a LAMMPS dump by `granshock export`, through
`granshock fields --from-dump` (docs/fields.md, section 13) give the densities and
velocities that summing the same particles directly gives: the round trip of the export.

granshock runs apps/bench/lammps/small_bow_shock.toml with a snapshot every 0.5 ms; the
snapshots of its production window (run.h5 /particles/all, docs/output_format.md) become
the frames of a LAMMPS `dump custom` (`granshock export --lammps-dump`, every value checked
against run.h5) and the run's resolved scene with a [dump] table the map (`--map`). This script bins the same particles
itself, by the rule of docs/fields.md (section 1 and section 13: x wrapped into the
periodic width, the wrapping column, the last row clipped at the outlet), on the grid
fields.h5 names, and compares n_s, mean_count and phi in every bin, and ux_s, uy_s where
the analysis gives them, with fields.h5. Prints PASS or FAIL lines.

Usage: check_snapshot_dump.py GRANSHOCK SOURCE_DIR
"""
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"FAIL: {' '.join(cmd)} exited {r.returncode}: {r.stderr.strip()}")


def snapshots(run_h5, start, end):
    """The snapshots with start <= t < end: time, positions, velocities, species, ids."""
    frames = []
    with h5py.File(run_h5, "r") as f:
        times = f["particles/all/count/time"][()]
        counts = f["particles/all/count/value"][()]
        for k, t in enumerate(times):
            if not (start <= t < end):
                continue
            n = int(counts[k])
            frames.append(dict(t=float(t), x=f["particles/all/position/value"][k, :n],
                               v=f["particles/all/velocity/value"][k, :n],
                               species=f["particles/all/species/value"][k, :n],
                               id=f["particles/all/id/value"][k, :n]))
    return frames


def main():
    granshock, src = sys.argv[1], sys.argv[2]
    scene = os.path.join(src, "apps/bench/lammps/small_bow_shock.toml")
    start, end, dt = 0.006, 0.012, 2e-7
    with tempfile.TemporaryDirectory() as tmp:
        run([granshock, "run", scene, "--out", f"{tmp}/run", "--quiet", "--no-figures",
             "--set", f"time.duration={end}", "--set", f"time.production_start={start}",
             "--set", "output.snapshot_interval=0.0005", "--set", "output.blocks=3"])
        with h5py.File(f"{tmp}/run/run.h5", "r") as f:
            resolved = f["scene/resolved"][()]
            resolved = resolved.decode() if isinstance(resolved, bytes) else resolved
        frames = snapshots(f"{tmp}/run/run.h5", start, end)
        if len(frames) < 10:
            raise SystemExit(f"FAIL: only {len(frames)} snapshots in the window")
        width, length = 0.030, 0.048
        # `granshock export` writes the dump and its map (docs/output_format.md, "Export to
        # LAMMPS and OVITO"); every exported value must be the snapshot's, bit for bit.
        run([granshock, "export", f"{tmp}/run", "--lammps-dump", f"{tmp}/run.dump", "--map",
             f"{tmp}/map.toml", "--quiet"])
        check_export(f"{tmp}/run.dump", snapshots(f"{tmp}/run/run.h5", 0, float("inf")))
        run([granshock, "fields", "--from-dump", "lammps", f"{tmp}/run.dump", "--map",
             f"{tmp}/map.toml", "--out", f"{tmp}/out", "--no-figures"])
        with h5py.File(f"{tmp}/out/fields.h5", "r") as f:
            g = {k: f["grid"].attrs[k] for k in ("nx", "ny", "x0", "y0", "dx", "dy")}
            fields = {k: f[f"fields/{k}"][()] for k in f["fields"]}
            samples = f.attrs["samples"]
            names = f.attrs["species"]
            names = (names.decode() if isinstance(names, bytes) else names).split(",")
    check(frames, g, fields, samples, names, width, length)


def check_export(dump, frames):
    """The exported dump holds every snapshot, its atoms by id (granshock id + 1, species +
    1), with the snapshot's times, positions and velocities as the same doubles."""
    failures, k, lines = [], 0, open(dump).read().split("\n")
    i = 0
    while i < len(lines) and lines[i] == "ITEM: TIMESTEP":
        time = float(lines[i + 3])
        n = int(lines[i + 5])
        rows = np.array([[float(v) for v in line.split()] for line in lines[i + 11:i + 11 + n]])
        fr = frames[k]
        order = np.argsort(fr["id"])
        if time != fr["t"] or n != len(fr["id"]):
            failures.append(f"frame {k}: time {time} and {n} atoms, run.h5 {fr['t']} and {len(fr['id'])}")
        elif n and not (np.array_equal(rows[:, 0], fr["id"][order] + 1) and
                        np.array_equal(rows[:, 1], fr["species"][order] + 1) and
                        np.array_equal(rows[:, 2:4], fr["x"][order]) and
                        np.array_equal(rows[:, 5:7], fr["v"][order]) and
                        (rows[:, 8] == 0.0005).all()):
            failures.append(f"frame {k}: the atoms differ from run.h5's")
        i += 11 + n
        k += 1
    if k != len(frames):
        failures.append(f"the dump holds {k} frames, run.h5 {len(frames)}")
    for f in failures:
        print("FAIL: export:", f)
    print(f"export: {k} frames compared with run.h5")


def check(frames, g, fields, samples, names, width, length):
    nx, ny = int(g["nx"]), int(g["ny"])
    count = np.zeros((2, ny, nx))
    vx = np.zeros((2, ny, nx))
    vy = np.zeros((2, ny, nx))
    for fr in frames:
        for i in range(len(fr["id"])):
            x, y = float(fr["x"][i][0]) % width, float(fr["x"][i][1])
            fx, fy = (x - g["x0"]) / g["dx"], (y - g["y0"]) / g["dy"]
            if fy < 0:
                continue
            if fx < 0:
                fx += nx  # the column that wraps across the periodic boundary
            ix, iy = min(int(fx), nx - 1), int(fy)
            if iy >= ny:
                continue
            s = int(fr["species"][i])
            count[s, iy, ix] += 1
            vx[s, iy, ix] += float(fr["v"][i][0])
            vy[s, iy, ix] += float(fr["v"][i][1])
    k = len(frames)
    failures = []
    if samples != k:
        failures.append(f"fields.h5 has {samples} samples, the dump {k} frames")
    rows = np.arange(ny)
    area = g["dx"] * np.minimum(g["dy"], length - (g["y0"] + rows * g["dy"]))
    phi = np.zeros((ny, nx))
    compared = 0
    for s, name in enumerate(names):
        n = count[s] / (k * area[:, None])
        phi += n * math.pi * 1e-6 / 4
        if not np.allclose(fields[f"n_{name}"], n, rtol=1e-12, atol=0):
            failures.append(f"n_{name} differs by up to "
                            f"{np.nanmax(np.abs(fields[f'n_{name}'] - n) / n.max()):.3g}")
        for what, total in (("ux", vx[s]), ("uy", vy[s])):
            got = fields[f"{what}_{name}"]
            given = np.isfinite(got)
            compared += int(given.sum())
            want = total[given] / count[s][given]
            if not np.allclose(got[given], want, rtol=1e-10, atol=1e-14):
                failures.append(f"{what}_{name} differs")
    if not np.allclose(fields["phi"], phi, rtol=1e-12, atol=0):
        failures.append("phi differs")
    if not np.allclose(fields["mean_count"], count.sum(axis=0) / k, rtol=1e-12, atol=0):
        failures.append("mean_count differs")
    if compared < 20:
        failures.append(f"only {compared} species velocities to compare")
    print(f"{k} frames, {int(count.sum())} particle samples in {nx} x {ny} bins, "
          f"{compared} species velocities compared")
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("PASS")


if __name__ == "__main__":
    main()

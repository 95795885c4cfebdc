#!/usr/bin/python3
"""A granshock run's own particles, written as a LAMMPS dump, through `granshock fields
--from-dump` (docs/fields.md, section 13) give the densities and velocities that summing
the same particles directly gives.

granshock runs apps/bench/lammps/small_bow_shock.toml with a snapshot every 0.5 ms; the
snapshots of its production window (run.h5 /particles/all, docs/output_format.md) become
the frames of a LAMMPS `dump custom` (columns in LAMMPS' order, z and vz zero) and the
run's resolved scene with a [dump] table the map. This script bins the same particles
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
        with open(f"{tmp}/run.dump", "w") as out:
            for fr in frames:
                out.write(f"ITEM: TIMESTEP\n{round(fr['t'] / dt)}\nITEM: NUMBER OF ATOMS\n"
                          f"{len(fr['id'])}\nITEM: BOX BOUNDS pp ff pp\n0 {width!r}\n"
                          f"0 {length!r}\n-0.0005 0.0005\nITEM: ATOMS id type x y z vx vy vz\n")
                for i in range(len(fr["id"])):
                    x, v = fr["x"][i], fr["v"][i]
                    out.write(f"{fr['id'][i] + 1} {fr['species'][i] + 1} {float(x[0])!r} "
                              f"{float(x[1])!r} 0 {float(v[0])!r} {float(v[1])!r} 0\n")
        with open(f"{tmp}/map.toml", "w") as out:
            out.write(resolved + f'\n[dump]\ndt = {dt!r}\n\n[dump.types]\n1 = "steel"\n'
                      '2 = "aluminium"\n')
        run([granshock, "fields", "--from-dump", "lammps", f"{tmp}/run.dump", "--map",
             f"{tmp}/map.toml", "--out", f"{tmp}/out", "--no-figures"])
        with h5py.File(f"{tmp}/out/fields.h5", "r") as f:
            g = {k: f["grid"].attrs[k] for k in ("nx", "ny", "x0", "y0", "dx", "dy")}
            fields = {k: f[f"fields/{k}"][()] for k in f["fields"]}
            samples = f.attrs["samples"]
            names = f.attrs["species"]
            names = (names.decode() if isinstance(names, bytes) else names).split(",")
    check(frames, g, fields, samples, names, width, length)


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

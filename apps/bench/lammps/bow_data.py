#!/usr/bin/python3
"""Converts the last particle snapshot of a granshock bow-shock run (RUN_DIR/run.h5,
docs/output_format.md) into a LAMMPS data file, and prints the scene's geometry as LAMMPS
variables for bench_bow_shock.sh.

Usage: bow_data.py RUN_DIR OUT.data > scene.lmp

The LAMMPS side (contact_law.py) knows the paper's mixture only, so the scene must have
species steel then aluminium (types 1 and 2) of d = 1 mm, the built-in materials, one
restitution 0.5 without friction, a cylinder of aluminium, and be 2-D; anything else is
refused rather than converted into a different benchmark.
"""
import math
import os
import sys
import tomllib

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_law as law  # noqa: E402


def check_scene(s):
    problems = []
    if s["scene"]["dim"] != 2:
        problems.append("not 2-D")
    names = [sp["material"] for sp in s["species"]]
    if names != law.TYPES or any(sp["diameter"] != law.DIAMETER for sp in s["species"]):
        problems.append(f"species {names} are not {law.TYPES} of d = {law.DIAMETER} m")
    for name, (E, nu, rho) in law.MATERIALS.items():
        m = s["materials"][name]
        if (m["youngs_modulus"], m["poisson_ratio"]) != (E, nu) or abs(m["density"] / rho - 1) > 1e-12:
            problems.append(f"material {name} differs from core/material.cpp")
    c = s["contact"]
    if c["model"] != "hertz" or c["limit_force"]:
        problems.append("contact model is not hertz without limit_force")
    for pair in [c] + list(c.get("pairs", {}).values()):
        if pair["restitution"] != 0.5 or pair["friction"] != 0:
            problems.append("restitution is not 0.5 everywhere, or friction is on")
            break
    if s["obstacle"]["material"] != "aluminium":
        problems.append("the obstacle is not aluminium")
    if problems:
        raise SystemExit("bow_data.py: the scene is not the paper's: " + "; ".join(problems))


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    run_dir, out = sys.argv[1], sys.argv[2]
    with h5py.File(os.path.join(run_dir, "run.h5"), "r") as f:
        resolved = f["scene/resolved"][()]
        scene = tomllib.loads(resolved.decode() if isinstance(resolved, bytes) else resolved)
        count = f["particles/all/count"]
        n = int(count["value"][-1])
        time, step = float(count["time"][-1]), int(count["step"][-1])
        x = f["particles/all/position/value"][-1, :n]
        v = f["particles/all/velocity/value"][-1, :n]
        species = f["particles/all/species/value"][-1, :n]
    check_scene(scene)
    width, length = scene["domain"]["width"], scene["domain"]["length"]
    r = law.DIAMETER / 2
    inside = (x[:, 1] >= 0) & (x[:, 1] <= length)
    with open(out, "w") as f:
        f.write(f"granshock {scene['scene']['name']} at t = {time} s (step {step}) from {run_dir}\n\n")
        f.write(f"{int(inside.sum())} atoms\n2 atom types\n\n")
        f.write(f"0 {width!r} xlo xhi\n0 {length!r} ylo yhi\n{-r} {r} zlo zhi\n\n")
        # atom_style sphere: id type diameter density x y z (mass = 4/3 pi r^3 density).
        f.write("Atoms # sphere\n\n")
        k = 0
        for i in range(n):
            if inside[i]:
                k += 1
                rho = law.MATERIALS[law.TYPES[species[i]]][2]
                f.write(f"{k} {species[i] + 1} {law.DIAMETER} {rho!r} "
                        f"{x[i, 0] % width!r} {x[i, 1]!r} 0\n")
        f.write("\nVelocities\n\n")
        k = 0
        for i in range(n):
            if inside[i]:
                k += 1
                f.write(f"{k} {v[i, 0]!r} {v[i, 1]!r} 0 0 0 0\n")
    cx, cy = scene["obstacle"]["centre"]
    print(f"# {scene['scene']['name']} from {run_dir}, t = {time} s, {int(inside.sum())} particles")
    print(f"variable dt equal {scene['time']['dt']!r}")
    print(f"variable skin equal {scene['numerics']['skin']!r}")
    print(f"variable cx equal {cx!r}")
    print(f"variable cy equal {cy!r}")
    print(f"variable cr equal {scene['obstacle']['diameter'] / 2!r}")
    print(f"variable flux equal {scene['inflow']['area_fraction'] * width / (math.pi * r * r) * scene['inflow']['velocity']!r}")


if __name__ == "__main__":
    main()

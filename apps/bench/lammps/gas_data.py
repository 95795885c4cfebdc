#!/usr/bin/python3
"""Writes a LAMMPS data file of the homogeneous 2-D gas that granshock_bench_gas times
(cases/gas/homogeneous_gas.cpp): the paper's mixture (steel and aluminium alternating,
d = 1 mm), a periodic square box at area fraction PHI, particles on a square lattice of
side round(sqrt(N)) (so N is rounded to a full lattice, as in granshock), each jittered
uniformly within (spacing - d)/2 of its site so no two overlap, Gaussian velocities of
standard deviation SIGMA per component, centre-of-mass velocity removed. Different random
numbers from granshock's (numpy, seeded), the same distribution.

Usage: gas_data.py PHI N SIGMA OUT [SEED]
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_law as law  # noqa: E402


def main():
    if len(sys.argv) not in (5, 6):
        raise SystemExit(__doc__)
    phi, n_wanted, sigma, out = float(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    rng = np.random.default_rng(int(sys.argv[5]) if len(sys.argv) == 6 else 1)
    d = law.DIAMETER
    side = max(1, round(math.sqrt(n_wanted)))
    n = side * side
    length = math.sqrt(n * math.pi * d * d / 4 / phi)
    spacing = length / side
    room = spacing - d
    if room <= 0:
        raise SystemExit(f"area fraction {phi} is too dense for a square lattice")
    k = np.arange(n)
    x = (k % side + 0.5) * spacing + (rng.random(n) - 0.5) * room
    y = (k // side + 0.5) * spacing + (rng.random(n) - 0.5) * room
    types = k % 2 + 1  # 1 steel, 2 aluminium: equal number fractions
    v = rng.normal(0.0, sigma, (n, 2))
    rho = np.array([law.MATERIALS[t][2] for t in law.TYPES])[types - 1]
    mass = rho * math.pi * d**3 / 6
    v -= (mass[:, None] * v).sum(axis=0) / mass.sum()
    with open(out, "w") as f:
        f.write(f"granshock homogeneous gas: phi {phi}, {n} particles, sigma {sigma} m/s\n\n")
        f.write(f"{n} atoms\n2 atom types\n\n")
        f.write(f"0 {length!r} xlo xhi\n0 {length!r} ylo yhi\n{-d / 2} {d / 2} zlo zhi\n\n")
        # atom_style sphere: id type diameter density x y z (mass = 4/3 pi r^3 density).
        f.write("Atoms # sphere\n\n")
        for i in range(n):
            f.write(f"{i + 1} {types[i]} {d} {rho[i]!r} {x[i]!r} {y[i]!r} 0\n")
        f.write("\nVelocities\n\n")
        for i in range(n):
            f.write(f"{i + 1} {v[i, 0]!r} {v[i, 1]!r} 0 0 0 0\n")
    print(f"{n} particles, box {length:.6g} m, phi {phi}", file=sys.stderr)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Writes the LAMMPS side of the cross-check (README.md here): a granshock bow-shock scene
with granshock's inflow, as a LAMMPS data file and input.

Usage: lammps_inflow.py SCENE_RESOLVED.toml WORK_DIR [--sigma S] [--dump-every SECONDS]
                        [--seed N] [--ranks N]

SCENE_RESOLVED.toml is the scene as granshock resolved it (`granshock run SCENE
--dry-run` without its first comment line, or run.h5's /scene/resolved): SI units, the
paper's mixture (steel and aluminium, d = 1 mm, e = 0.5, no friction; the checks of
apps/bench/lammps/bow_data.py), an aluminium cylinder. --sigma overrides inflow.sigma
(the sigma a granshock run calibrated for inflow.mach, from its summary.json).

The inflow (granshock: docs/scene_format.md, "The inflow") is an upstream reservoir:
  * at t = 0 the box y in [-R, L] is filled at phi_inf (one random sequential placement,
    no overlaps, the obstacle left free), species drawn by their number fractions,
    velocities (0, U) + Gaussian sigma per component: y in [0, L] is granshock's
    prefilled domain, y in [-R, 0) the gas that will flow in;
  * the reservoir is held at the inflow state: every CHUNK steps (2e-4 s) every particle
    with y < 0 gets a new velocity (0, U) + Gaussian sigma (an Andersen thermostat to
    granshock's inserted state), so the gas that crosses y = 0 has phi_inf and the
    inserted velocity distribution, like granshock's strip, and is a gas of discs that
    never overlap deeply. Without it the reservoir would cool (e = 0.5) before it arrives;
  * its length: by default R = U T + 40 d, the whole run's inflow. With --refill-block B
    it is B + 20 d, and each time it has moved B downstream a fresh block of B d at
    phi_inf (a new placement, the same velocity law) is read in behind it (read_data add
    append), the new discs that touch one of the old ones deleted (delete_atoms
    overlap): the same inflow at a fraction of the cost;
  * particles leaving the box (y > L) are lost (boundary f, `thermo_modify lost ignore`),
    as granshock deletes them at the outlet; one that turns back across y = 0 rejoins
    the reservoir instead of being deleted (granshock deletes it; the shock stands far
    downstream of the inlet here).
The cylinder and the contact law are apps/bench/lammps/bench_bow_shock.sh's (open-capped
region cylinder, one fix wall/gran/region per species, contact_law.py). The dump holds
the particles with y >= 0 from production_start on, every --dump-every seconds.
"""
import argparse
import math
import os
import random
import sys
import tomllib

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "apps", "bench", "lammps"))
import bow_data  # noqa: E402  (the scene checks)
import contact_law as law  # noqa: E402

CHUNK_SECONDS = 2e-4  # the reservoir's velocities are redrawn this often
MARGIN_D = 40  # reservoir length beyond U T, in d


def place(rng, n, width, y0, y1, r, free):
    """Random sequential placement of n discs of radius r in [0, width) x [y0, y1),
    periodic in x, no two closer than 2 r, each where free(x, y) holds."""
    cell = 2 * r
    nx = max(1, int(width // cell))
    cw = width / nx
    grid = {}
    pts = []
    tries = 0
    while len(pts) < n:
        tries += 1
        if tries > 200 * n:
            raise SystemExit(f"lammps_inflow.py: could not place {n} discs")
        x, y = rng.uniform(0, width), rng.uniform(y0, y1)
        if not free(x, y):
            continue
        ix, iy = int(x / cw) % nx, int((y - y0) // cell)
        ok = True
        for jx in (ix - 1, ix, ix + 1):
            for jy in (iy - 1, iy, iy + 1):
                for (px, py) in grid.get((jx % nx, jy), ()):
                    dx = x - px
                    dx -= width * round(dx / width)
                    if dx * dx + (y - py) ** 2 < cell * cell:
                        ok = False
                        break
                if not ok:
                    break
            if not ok:
                break
        if ok:
            grid.setdefault((ix, iy), []).append((x, y))
            pts.append((x, y))
    return pts


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("scene")
    p.add_argument("work")
    p.add_argument("--sigma", type=float)
    p.add_argument("--dump-every", type=float, default=5e-4)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--refill-block", type=float, default=0,
                   help="B in d: a reservoir of B + 20 d, refilled with B d of fresh gas each "
                   "time it has moved B (default 0: one reservoir of U T + 40 d)")
    a = p.parse_args()
    with open(a.scene, "rb") as f:
        s = tomllib.load(f)
    bow_data.check_scene(s)
    os.makedirs(a.work, exist_ok=True)
    rng = random.Random(a.seed)
    width, length = s["domain"]["width"], s["domain"]["length"]
    inflow = s["inflow"]
    phi, U = inflow["area_fraction"], inflow["velocity"]
    sigma = a.sigma if a.sigma is not None else inflow["sigma"]
    dt, T, t0 = s["time"]["dt"], s["time"]["duration"], s["time"]["production_start"]
    d = law.DIAMETER
    r = d / 2
    (cx, cy), D = s["obstacle"]["centre"], s["obstacle"]["diameter"]
    chunk = max(1, round(CHUNK_SECONDS / dt))
    if a.refill_block > 0:
        # A short reservoir, refilled: between B + 20 d and 20 d long.
        block = round(a.refill_block) * d
        res = block + 20 * d
        if abs(block / U / (chunk * dt) - round(block / U / (chunk * dt))) > 1e-9:
            raise SystemExit("lammps_inflow.py: B / U is not a whole number of chunks")
    else:
        block = 0.0
        res = math.ceil((U * T) / d + MARGIN_D) * d
    n_res = round(phi * width * res / (math.pi * r * r))
    n_dom = round(phi * (width * length - math.pi * D * D / 4) / (math.pi * r * r))
    reach = (D / 2 + r) ** 2
    free = lambda x, y: (x - cx) ** 2 + (y - cy) ** 2 >= reach
    # One placement for reservoir and domain, so that no two discs overlap across y = 0.
    pts = place(rng, n_res + n_dom, width, -res, length, r, free)
    fractions = [sp["number_fraction"] for sp in s["species"]]
    box = f"0 {width!r} xlo xhi\n{-res!r} {length!r} ylo yhi\n{-r} {r} zlo zhi\n\n"

    def write_data(name, title, points):
        with open(os.path.join(a.work, name), "w") as f:
            f.write(title + "\n\n")
            f.write(f"{len(points)} atoms\n2 atom types\n\n{box}Atoms # sphere\n\n")
            types = [1 if rng.random() < fractions[0] else 2 for _ in points]
            for k, ((x, y), t) in enumerate(zip(points, types), 1):
                rho = law.MATERIALS[law.TYPES[t - 1]][2]
                f.write(f"{k} {t} {d} {rho!r} {x!r} {y!r} 0\n")
            f.write("\nVelocities\n\n")
            for k in range(1, len(points) + 1):
                f.write(f"{k} {rng.gauss(0, sigma)!r} {U + rng.gauss(0, sigma)!r} 0 0 0 0\n")

    write_data("inflow.data", f"granshock {s['scene']['name']} with an upstream reservoir of "
               f"{res / d:.0f} d (docs/results/cross_check/lammps_inflow.py)", pts)
    # Refills: a fresh block of B d behind the reservoir's rear each time it has moved B.
    refills = []
    if block:
        n_block = round(phi * width * block / (math.pi * r * r))
        every_chunks = round(block / U / (chunk * dt))
        for k in range(1, math.ceil((T / dt / chunk) / every_chunks)):
            write_data(f"block_{k}.data", f"refill {k}: y in [-R, -R + B)",
                       place(rng, n_block, width, -res, -res + block, r, lambda x, y: True))
            refills.append((k * every_chunks, f"block_{k}.data"))
    with open(os.path.join(a.work, "pairs.lmp"), "w") as f:
        f.write("\n".join(law.pair_coeffs(0.5)) + "\n")
    with open(os.path.join(a.work, "walls.lmp"), "w") as f:
        f.write("\n".join(law.wall_fixes(0.5, "cyl")) + "\n")
    spin = round(t0 / dt / chunk)
    prod = round((T - t0) / dt / chunk)
    every = round(a.dump_every / dt)
    if (chunk * spin) % every:
        raise SystemExit("lammps_inflow.py: production_start is not on the dump's grid")
    seed = 1000 + a.seed
    procs = "processors * 1 1" if a.ranks > 1 else ""
    inp = f"""# granshock scene {s['scene']['name']} in LAMMPS with granshock's inflow
# (docs/results/cross_check/lammps_inflow.py): sigma = {sigma!r} m/s, reservoir {res / d:.0f} d,
# {n_res} + {n_dom} particles, velocities redrawn at y < 0 every {chunk} steps.
units si
dimension 2
boundary p f p
atom_style sphere
comm_modify vel yes
{procs}
read_data inflow.data
group steel type 1
group aluminium type 2
pair_style granular
include pairs.lmp
region cyl cylinder z {cx!r} {cy!r} {D / 2!r} INF INF open 1 open 2 side out units box
include walls.lmp
neighbor {s['numerics']['skin']!r} bin
neigh_modify delay 0 every 1 check yes
fix integrate all nve/sphere
fix plane all enforce2d
timestep {dt!r}
variable nvx atom (y<0)*normal(0.0,{sigma!r},{seed})+(y>=0)*vx
variable nvy atom (y<0)*({U!r}+normal(0.0,{sigma!r},{seed + 1}))+(y>=0)*vy
thermo_style custom step time atoms ke
thermo_modify lost ignore norm no
thermo {chunk * 50}
{{body}}print "CROSS_CHECK_DONE"
"""
    body = ["run 0 post no"]
    inserts = dict(refills)
    for c in range(spin + prod):
        if c == spin:
            body += [f"dump frames all custom {every} frames.dump id type x y z vx vy vz",
                     "dump_modify frames sort id thresh y >= 0.0"]
        if c in inserts:
            body += ["group old union all",
                     f"read_data {inserts[c]} add append group newblock",
                     f"delete_atoms overlap {d!r} newblock old compress no",
                     "group steel type 1", "group aluminium type 2",
                     "group newblock delete", "group old delete"]
        if c == spin or c in inserts:
            body.append("run 0 post no")
        body += [f"run {chunk} pre no post no", "set group all vx v_nvx vy v_nvy"]
    inp = inp.replace("{body}", "\n".join(body) + "\n")
    with open(os.path.join(a.work, "run.in"), "w") as f:
        f.write(inp)
    print(f"{s['scene']['name']}: {len(pts)} particles ({n_res} in the {res / d:.0f} d reservoir), "
          f"{(spin + prod) * chunk} steps of {dt} s in chunks of {chunk}, sigma {sigma}",
          file=sys.stderr)


if __name__ == "__main__":
    main()

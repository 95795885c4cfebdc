#!/usr/bin/python3
"""The LAMMPS side of check_contact_law.sh: a head-on collision set up as `granshock
collide` sets it up (cases/collision/head_on_collision.cpp), and its measurement.

  collision.py input COLLIDE_JSON PREFIX   writes PREFIX.in and PREFIX.data; the input
      includes pairs.lmp and walls.lmp (contact_law.py pairs / walls E cyl) from PREFIX's folder
  collision.py compare COLLIDE_JSON LOG TOL       prints both codes' e_eff and t_contact
"""
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_law as law  # noqa: E402

R = law.DIAMETER / 2
CYLINDER_RADIUS = 5 * law.DIAMETER  # collide's cylinder: diameter 10 d, at the origin


def bodies(pair):
    a, b = pair.split("-")
    return a, (None if b == "obstacle" else b)


def write_input(collide, prefix):
    a, b = bodies(collide["pair"])
    v, dt = collide["speed"], collide["dt"]
    gap0 = 5.0 * v * dt
    # (type, x, vx) as collide starts them: two particles in the zero-momentum frame, or
    # one particle moving at v towards the cylinder's -x side.
    if b is None:
        atoms = [(law.TYPES.index(a) + 1, -(CYLINDER_RADIUS + R + gap0), v)]
    else:
        ma, mb = law.mass(a), law.mass(b)
        atoms = [(law.TYPES.index(a) + 1, -(R + 0.5 * gap0), v * mb / (ma + mb)),
                 (law.TYPES.index(b) + 1, R + 0.5 * gap0, -v * ma / (ma + mb))]
    half = 0.02
    with open(prefix + ".data", "w") as f:
        f.write(f"granshock collide {collide['pair']}\n\n{len(atoms)} atoms\n2 atom types\n\n")
        f.write(f"{-half} {half} xlo xhi\n{-half} {half} ylo yhi\n{-R} {R} zlo zhi\n\n")
        # atom_style sphere: id type diameter density x y z; LAMMPS sets the mass to
        # 4/3 pi r^3 density, the 3-D sphere mass, also in 2-D.
        f.write("Atoms # sphere\n\n")
        for i, (t, x, _) in enumerate(atoms, 1):
            rho = law.MATERIALS[law.TYPES[t - 1]][2]
            f.write(f"{i} {t} {law.DIAMETER!r} {rho!r} {x!r} 0 0\n")
        f.write("\nVelocities\n\n")
        for i, (_, _, vx) in enumerate(atoms, 1):
            f.write(f"{i} {vx!r} 0 0 0 0 0\n")
    name = os.path.basename(prefix)
    steps = collide["steps"] + 20  # collide stops the step the contact ends
    vars2 = "" if b is None else "v_x2 v_vx2 "
    with open(prefix + ".in", "w") as f:
        f.write(f"""# head-on collision {collide['pair']}, as granshock collide
units si
dimension 2
boundary f f p
atom_style sphere
atom_modify map array
comm_modify vel yes
read_data {name}.data
group steel type 1
group aluminium type 2
pair_style granular
include pairs.lmp
neighbor {0.3 * law.DIAMETER} bin
neigh_modify delay 0 every 1 check yes
region cyl cylinder z 0 0 {CYLINDER_RADIUS} INF INF open 1 open 2 side out units box
{'' if b is None else '# ' }include walls.lmp
fix integrate all nve/sphere
timestep {dt!r}
variable x1 equal x[1]
variable vx1 equal vx[1]
variable m1 equal mass[1]
{'' if b is None else 'variable x2 equal x[2]'}
{'' if b is None else 'variable vx2 equal vx[2]'}
{'' if b is None else 'variable m2 equal mass[2]'}
print "MASS ${{m1}} {'' if b is None else '${m2}'}"
thermo_style custom step v_x1 v_vx1 {vars2}
thermo_modify format float %.17g norm no
thermo 1
run {steps}
""")


def read_log(path):
    masses, rows, in_run = None, [], False
    for line in open(path):
        words = line.split()
        if line.startswith("MASS "):
            masses = [float(w) for w in words[1:]]
        elif words[:1] == ["Step"]:
            in_run = True
        elif line.startswith("Loop time"):
            in_run = False
        elif in_run and words:
            rows.append([float(w) for w in words])
    return masses, rows


def measure(pair, dt, rows):
    """e_eff and t_contact as collide measures them, from per-step positions/velocities."""
    a, b = bodies(pair)

    def gap(r):
        if b is None:
            return abs(r[1]) - R - CYLINDER_RADIUS
        return abs(r[3] - r[1]) - 2 * R

    def separation_speed(r):
        return -r[2] if b is None else r[4] - r[2]

    prev, t_start, t_end, end = gap(rows[0]), None, None, None
    for r in rows[1:]:
        now, t = gap(r), r[0] * dt
        if prev > 0 and now <= 0 and t_start is None:
            t_start = t - dt * now / (now - prev)
        if prev <= 0 and now > 0 and t_start is not None:
            t_end, end = t - dt * now / (now - prev), r
            break
        prev = now
    if t_end is None:
        raise SystemExit(f"{pair}: the LAMMPS collision did not complete")
    return separation_speed(end) / -separation_speed(rows[0]), t_end - t_start


def compare(collide, log, tol):
    pair = collide["pair"]
    a, b = bodies(pair)
    masses, rows = read_log(log)
    want = [law.mass(a)] + ([] if b is None else [law.mass(b)])
    if masses is None or any(abs(m / w - 1) > 1e-12 for m, w in zip(masses, want)):
        raise SystemExit(f"{pair}: LAMMPS masses {masses} are not granshock's {want}")
    e_l, t_l = measure(pair, collide["dt"], rows)
    e_g, t_g = collide["e_eff"], collide["t_contact"]
    de, dt = e_l / e_g - 1, t_l / t_g - 1
    ok = abs(de) <= tol and abs(dt) <= tol
    print(f"{pair:19s} e_eff granshock {e_g:.9f} LAMMPS {e_l:.9f} rel.diff {de:+.2e} | "
          f"t_contact granshock {t_g:.6e} s LAMMPS {t_l:.6e} s rel.diff {dt:+.2e}"
          f"{'' if ok else '  <-- exceeds ' + str(tol)}")
    return ok


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "input":
        write_input(json.load(open(sys.argv[2])), sys.argv[3])
    elif len(sys.argv) == 5 and sys.argv[1] == "compare":
        sys.exit(0 if compare(json.load(open(sys.argv[2])), sys.argv[3], float(sys.argv[4])) else 1)
    else:
        raise SystemExit(__doc__)


if __name__ == "__main__":
    main()

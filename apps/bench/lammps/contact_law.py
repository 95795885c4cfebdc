#!/usr/bin/python3
"""granshock's contact law written as LAMMPS commands, for the scripts in this folder.

LAMMPS: the Debian 12 package `lammps` 20220106.git7586adbb6a+ds1-2 (LAMMPS "29 Sep 2021
- Update 2", GRANULAR package, Open MPI). The factors below were checked against that
version's source (src/GRANULAR/pair_granular.cpp, fix_wall_gran.cpp, src/region_cylinder.cpp,
from `apt-get source lammps`) and doc/src/pair_granular.rst
(https://docs.lammps.org/pair_granular.html).

Derivation: LIGGGHTS `hertz` (granshock, docs/contact_model.md) against LAMMPS `granular`
-----------------------------------------------------------------------------------------
granshock:  Fn = kn dn - gn vn,  kn = 4/3 Y* sqrt(R* dn),
            gn = -2 sqrt(5/6) beta sqrt(Sn m*),  Sn = 2 Y* sqrt(R* dn) = 3/2 kn,
            beta = ln e / sqrt(ln^2 e + pi^2),
            1/Y* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j  (core/pair_properties.cpp).
  So gn = 2 sqrt(5/6) |beta| sqrt(3/2) sqrt(kn m*) = sqrt(5) |beta| sqrt(kn m*).

LAMMPS pair granular, `hertz/material E e nu ... damping tsuji`:
  pair_coeff i j stores k = 4/3 mix_stiffnessE(E, E, nu, nu) = 4/3 E / (2 (1 - nu^2)),
  i.e. 4/3 Y* of two bodies of that material (the docs' E_eff). In compute():
  a = sqrt(R_eff delta), knfac = k a, Fne = knfac delta, Fdamp = -alpha sqrt(meff knfac) vn,
  no clamp unless `limit_damping`. So knfac is granshock's kn and
  eta_n = alpha sqrt(m* kn): the laws agree when alpha = sqrt(5) |beta|.
  With `damping tsuji` the coefficient given in place of the damping is read as a
  restitution e' and replaced by Tsuji et al.'s fit (Tsuji, Tanaka & Ishida 1992, Powder
  Technol. 71, 239; LAMMPS docs, "damping tsuji"):
    alpha(e') = 1.2728 - 4.2783 e' + 11.087 e'^2 - 22.348 e'^3 + 27.467 e'^4
                - 18.022 e'^5 + 4.8218 e'^6.
  alpha is decreasing on [0, 1], so alpha(e') = sqrt(5) |beta(e)| has one root, found here
  by bisection: e = 0.5 needs e' = 0.36665 (alpha = 0.48177). e' is NOT the restitution
  LAMMPS then produces by Tsuji's reckoning; it is only the input that gives the same
  dashpot as granshock's e. check_contact_law.sh verifies it by head-on collisions.

Three traps in this LAMMPS version, avoided by giving the stiffness explicitly:
  * unlike pairs left to mixing (init_one) get k = mix_stiffnessE(...) WITHOUT the 4/3;
  * fix wall/gran hertz/material stores E / (2 (1 - nu)) * 4/3 (1 - nu, not 1 - nu^2);
  * a closed region cylinder reports a curvature radius 2 R for its side, so the wall's
    R_eff = r 2R / (r + 2R); with `open 1 open 2` it reports 0 and R_eff = r, which is
    granshock's wall of infinite radius (R* = r_i, m* = m_i).
So like pairs use hertz/material with the real E and nu (LAMMPS' own E_eff), and the
unlike pair and the walls use `hertz` with k = 4/3 Y* from the formula above.

Mass: read_data's sphere density gives m = 4/3 pi r^3 rho even with `dimension 2`
(atom_vec_sphere.cpp, data_atom_post), granshock's 3-D sphere mass (core/material.cpp).
Frictionless: `tangential linear_nohistory 0 0` (x_gamma_t = 0, mu = 0) gives Ft = 0
and keeps no contact history (no fix neigh/history), the cheapest tangential model.
"""
import argparse
import math

# core/material.cpp: name -> (E in Pa, Poisson ratio, density in kg/m^3); type = index + 1.
MATERIALS = {
    "steel": (210e9, 0.303, 7850.0),
    "aluminium": (69e9, 0.33, 7850.0 / 2.907),
}
TYPES = ["steel", "aluminium"]  # LAMMPS atom types 1 and 2
DIAMETER = 1e-3  # m, the paper's d


def youngs_star(a, b):
    inv = lambda m: (1 - MATERIALS[m][1] ** 2) / MATERIALS[m][0]
    return 1.0 / (inv(a) + inv(b))


def mass(material, diameter=DIAMETER):
    return MATERIALS[material][2] * math.pi * diameter**3 / 6.0


def beta(e):
    l = math.log(e)
    return l / math.sqrt(l * l + math.pi**2)


def tsuji_alpha(c):
    return (1.2728 - 4.2783 * c + 11.087 * c**2 - 22.348 * c**3 + 27.467 * c**4
            - 18.022 * c**5 + 4.8218 * c**6)


def tsuji_input(e):
    """The e' for which LAMMPS' tsuji alpha(e') equals sqrt(5) |beta(e)|."""
    target = math.sqrt(5.0) * abs(beta(e))
    lo, hi = 0.0, 1.0
    if not tsuji_alpha(hi) <= target <= tsuji_alpha(lo):
        raise SystemExit(f"e = {e}: alpha = {target} is outside Tsuji's fit on [0, 1]")
    for _ in range(200):  # alpha decreases on [0, 1]: plain bisection
        mid = 0.5 * (lo + hi)
        if tsuji_alpha(mid) > target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def pair_coeffs(e):
    """LAMMPS pair_style granular coefficients for types 1 (steel) and 2 (aluminium)."""
    ep = tsuji_input(e)
    tail = "tangential linear_nohistory 0 0 damping tsuji"
    lines = []
    for i, a in enumerate(TYPES, 1):
        for j, b in enumerate(TYPES, 1):
            if j < i:
                continue
            if a == b:
                E, nu, _ = MATERIALS[a]
                lines.append(f"pair_coeff {i} {j} hertz/material {E:.17g} {ep:.17g} {nu} {tail}")
            else:
                k = 4.0 / 3.0 * youngs_star(a, b)
                lines.append(f"pair_coeff {i} {j} hertz {k:.17g} {ep:.17g} {tail}")
    return lines


def wall_fixes(e, region, obstacle="aluminium"):
    """One fix wall/gran/region per species group (the wall has a single coefficient set,
    and granshock's Y* differs by species). The groups must be named after TYPES."""
    ep = tsuji_input(e)
    lines = []
    for a in TYPES:
        k = 4.0 / 3.0 * youngs_star(a, obstacle)
        lines.append(f"fix wall_{a} {a} wall/gran/region granular hertz {k:.17g} {ep:.17g} "
                     f"tangential linear_nohistory 0 0 damping tsuji region {region}")
    return lines


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="what", required=True)
    t = sub.add_parser("tsuji", help="print the tsuji input e' for restitution e")
    t.add_argument("e", type=float)
    c = sub.add_parser("pairs", help="print the pair_coeff commands for restitution e")
    c.add_argument("e", type=float)
    w = sub.add_parser("walls", help="print fix wall/gran/region commands for restitution e "
                       "(groups steel and aluminium, an aluminium obstacle)")
    w.add_argument("e", type=float)
    w.add_argument("region")
    m = sub.add_parser("mass", help="print the mass of a d = 1 mm sphere of a material")
    m.add_argument("material", choices=TYPES)
    a = p.parse_args()
    if a.what == "mass":
        print(f"{mass(a.material):.17g}")
    elif a.what == "tsuji":
        print(f"{tsuji_input(a.e):.17g}")
    else:
        print(f"# granshock's hertz law (LIGGGHTS), e = {a.e}: tsuji input e' = "
              f"{tsuji_input(a.e):.10f}, alpha = sqrt(5)|beta| = "
              f"{math.sqrt(5) * abs(beta(a.e)):.10f} (apps/bench/lammps/contact_law.py)")
        print("\n".join(pair_coeffs(a.e) if a.what == "pairs" else wall_fixes(a.e, a.region)))


if __name__ == "__main__":
    main()

"""The wedge's shock angle against the theta-beta-Ma relation (docs/results/shapes/README.md).

Usage: theta_beta.py OUT_PNG RUN_DIR...   (runs of scenes/wedge.toml at several half-angles)

For each run: the shock angle of each flank measured near the wedge (a least-squares line
through the phi half-way front of fields.h5 /front/y_threshold in the columns from two
bins to one frontal width D from the axis, beside the wedge's faces, where an attached
oblique shock is straight), the analysis' own far-field angle (summary.json
shock_angle_deg: the same front fitted beyond D from the axis, docs/fields.md section 5),
and the oblique-shock prediction at the measured upstream state: Ma and phi
from the rows just beyond the insertion strip (/upstream/downstream) and from the bins
just upstream of the wedge's tip on the axis, gamma from the granular equation of state
of docs/fields.md at that phi: a^2 = gamma p / rho with p = n T F(phi), so
gamma = 1 + (2/Dim) F + (phi/F) dF/dphi (core/kinetic_theory.hpp, Dim = 2).
"""
import json
import math
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def gamma_eos(phi, e, dim=2):
    g = (16 - 7 * phi) / (16 * (1 - phi) ** 2)
    dg = (25 - 7 * phi) / (16 * (1 - phi) ** 3)
    f = 1 + (dim - 1) * (1 + e) * phi * g
    df = (dim - 1) * (1 + e) * (g + phi * dg)
    return 1 + 2 / dim * f + phi / f * df


def theta_of_beta(beta, mach, gamma):
    return np.arctan(2 / np.tan(beta) * (mach**2 * np.sin(beta) ** 2 - 1)
                     / (mach**2 * (gamma + np.cos(2 * beta)) + 2))


def weak_beta(theta_deg, mach, gamma):
    """The weak oblique shock's angle (deg), or NaN past the detachment angle."""
    betas = np.linspace(math.asin(1 / mach) + 1e-9, math.pi / 2 - 1e-9, 200001)
    thetas = theta_of_beta(betas, mach, gamma)
    top = int(np.argmax(thetas))
    if math.radians(theta_deg) > thetas[top]:
        return float("nan"), math.degrees(thetas[top])
    k = int(np.argmin(np.abs(thetas[:top + 1] - math.radians(theta_deg))))
    return math.degrees(betas[k]), math.degrees(thetas[top])


def near_tip_state(f, scene_tip_y, xc, d):
    """Mean Ma and phi of the unmasked bins 10 d to 20 d upstream of the tip, |x - xc| <= 5 d."""
    x, y = f["grid/x"][...], f["grid/y"][...]
    masked = f["fields/masked"][...] != 0
    cols = np.abs(x - xc) <= 5 * d
    rows = (y >= scene_tip_y - 20 * d) & (y <= scene_tip_y - 10 * d)
    sel = np.outer(rows, cols) & ~masked
    return float(np.mean(f["fields/Ma"][...][sel])), float(np.mean(f["fields/phi"][...][sel]))


def main():
    out_png, runs = sys.argv[1], sys.argv[2:]
    rows = []
    for run in runs:
        summary = json.load(open(f"{run}/summary.json"))
        with h5py.File(f"{run}/fields.h5", "r") as f:
            a = f.attrs
            d, xc = float(a["d"]), float(a["obstacle_xc"])
            face, back, width = float(a["obstacle_face"]), float(a["obstacle_back"]), float(a["obstacle_width"])
            theta = math.degrees(math.atan(0.5 * width / (back - face)))
            e = float(a["restitution"])
            dx_bin = float(f["grid"].attrs["dx"])
            fx, fy = f["front/x"][...], f["front/y_threshold"][...]
            flanks = []
            for side in (-1, 1):
                off = side * (fx - xc)
                sel = (off >= 2 * dx_bin - 1e-9) & (off <= width + 1e-9) & np.isfinite(fy)
                if np.count_nonzero(sel) >= 3:
                    slope, _ = np.polyfit(off[sel], fy[sel], 1)  # dy / d|x - xc|
                    flanks.append((math.degrees(math.atan(1 / slope)), int(np.count_nonzero(sel))))
            up = f["upstream/downstream"].attrs
            ma_in = float(summary["ma_inf_measured_downstream"])
            phi_in = float(up["phi"])
            ma_tip, phi_tip = near_tip_state(f, face, xc, d)
        delta = summary.get("delta_over_D")
        for where, mach, phi in (("inlet rows", ma_in, phi_in), ("ahead of the tip", ma_tip, phi_tip)):
            gamma = gamma_eos(phi, e)
            beta, theta_max = weak_beta(theta, mach, gamma)
            rows.append(dict(run=run, e=e, theta=theta, where=where, mach=mach, phi=phi, gamma=gamma,
                             beta_pred=beta, theta_max=theta_max, flanks=flanks,
                             beta_meas=summary.get("shock_angle_deg"), delta_over_D=delta,
                             duration=summary.get("simulated_seconds", summary.get("time"))))
    for r in rows:
        flanks = ", ".join(f"{b:.1f} ({n} columns)" for b, n in r["flanks"])
        near = float(np.mean([b for b, _ in r["flanks"]])) if r["flanks"] else float("nan")
        far = r["beta_meas"]
        print(f"{r['run']}: theta {r['theta']:.1f} deg; state {r['where']}: Ma {r['mach']:.2f}, phi {r['phi']:.4f}, "
              f"gamma {r['gamma']:.3f}, theta_max {r['theta_max']:.1f} deg; beta predicted {r['beta_pred']:.1f} deg; "
              f"measured near the wedge {near:.1f} deg (flanks {flanks}), measured - predicted "
              f"{near - r['beta_pred']:.1f} deg; far-field shock_angle_deg {far}; delta/D {r['delta_over_D']}")
    fig, ax = plt.subplots(figsize=(6, 4.2))
    betas = np.linspace(0.01, math.pi / 2 - 0.001, 2000)
    colours = {}
    for r in rows:  # one curve per restitution and state: the first run's
        key = (r["e"], r["where"])
        if key in colours:
            continue
        restitutions = sorted({k[0] for k in colours} | {r["e"]})
        colour = colours.setdefault(key, f"C{restitutions.index(r['e'])}")
        th = np.degrees(theta_of_beta(betas, r["mach"], r["gamma"]))
        ok = th > 0
        ax.plot(th[ok], np.degrees(betas[ok]), lw=1, color=colour,
                ls="-" if r["where"] == "inlet rows" else "--",
                label=f"e = {r['e']:g}: theory at Ma {r['mach']:.1f}, gamma {r['gamma']:.2f} ({r['where']})")
    for r in rows[::2]:
        for b, _ in r["flanks"]:
            ax.plot([r["theta"]], [b], "o", ms=5, color=colours[(r["e"], "inlet rows")], mec="k")
    ax.plot([0, 45], [0, 45], ":", color="0.5", lw=1, label="beta = theta (the face)")
    ax.plot([], [], "o", color="w", mec="k", label="measured, each flank (phi half-way front, 2 bins to D)")
    ax.set_xlabel("wedge half-angle theta (deg)")
    ax.set_ylabel("shock angle beta (deg)")
    ax.set_xlim(0, 45)
    ax.set_ylim(0, 90)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(out_png, dpi=130)


if __name__ == "__main__":
    main()

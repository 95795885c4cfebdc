#!/usr/bin/python3
"""The cross-check's table and figures (README.md here) from granshock analyses of one
scene: a granshock run directory and `granshock fields --from-dump` output directories,
each with summary.json, fields.h5 and detachment_convergence.csv (docs/output_format.md).

Usage: compare.py OUT_PREFIX LABEL=DIR [LABEL=DIR ...]

Writes OUT_PREFIX.csv (one row per analysis), OUT_PREFIX.md (the tables of README.md),
OUT_PREFIX_profiles.png (phi and T/(m U^2) on the stagnation line, every analysis on one
plot) and OUT_PREFIX_phi.png (the phi fields side by side, the first two analyses).
"""
import csv
import json
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# docs/fields.md, section 6: the definitions of delta, the primary first.
DEFINITIONS = [
    ("temperature_jump", "T half-rise (primary)"),
    ("sonic_line", "sonic point"),
    ("density_threshold", "phi half-way"),
    ("density_max_gradient", "steepest phi rise"),
    ("temperature_fit", "T fit"),
    ("density_fit", "phi fit"),
]


def load(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        s = json.load(f)
    halves = {}
    with open(os.path.join(directory, "detachment_convergence.csv")) as f:
        for row in csv.DictReader(f):
            if row["kind"] == "window":
                halves["first" if row["choice"].startswith("first") else "second"] = row
    with h5py.File(os.path.join(directory, "fields.h5"), "r") as h:
        up = {k: dict(h["upstream"][k].attrs) for k in ("inlet", "downstream")}
        prof = {k: h["profile"][k][()] for k in ("y", "phi", "T_norm", "masked")}
        pa = dict(h["profile"].attrs)
        g = dict(h["grid"].attrs)
        phi = h["fields/phi"][()]
        samples = h.attrs.get("samples")
        obstacle = [h.attrs[k] for k in ("obstacle_xc", "obstacle_yc", "obstacle_width")]
    return dict(s=s, halves=halves, up=up, prof=prof, pattrs=pa, grid=g, phi=phi,
                samples=samples, obstacle=obstacle)


def num(x, digits=3):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "n/a"
    return f"{x:.{digits}f}"


def pm(v, e):
    return f"{num(v)} +- {num(e)}" if v is not None else "n/a"


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    prefix = sys.argv[1]
    runs = []
    for arg in sys.argv[2:]:
        label, directory = arg.split("=", 1)
        runs.append((label, load(directory)))
    rows = []
    for label, r in runs:
        s, up = r["s"], r["up"]
        row = {"analysis": label, "samples": int(r["samples"]) if r["samples"] is not None else "",
               "Ma_inlet_rows": up["inlet"]["Ma"], "Ma_inlet_rows_paper_sum": up["inlet"]["Ma_paper_sum"],
               "phi_inlet_rows": up["inlet"]["phi"], "Ma_rows_2_4": up["downstream"]["Ma"],
               "phi_rows_2_4": up["downstream"]["phi"], "phi_peak": s.get("phi_peak"),
               "upstream_ma_peak": s.get("upstream_ma_peak"), "shock_angle_deg": s.get("shock_angle_deg"),
               "shock_layer_phi_mean": s.get("shock_layer_phi_mean"),
               "primary_largest_change_over_D":
                   s["detachment_convergence"]["verdicts"]["temperature_jump"]["max_deviation_over_D"]}
        for key, _ in DEFINITIONS:
            d = s["detachment"][key]
            row[key] = d["delta_over_D"]
            row[key + "_err"] = d["delta_over_D_err"]
            h1, h2 = r["halves"].get("first"), r["halves"].get("second")
            try:
                a, ea, b, eb = (float(h1[key]), float(h1[key + "_err"]), float(h2[key]),
                                float(h2[key + "_err"]))
                row[key + "_halves"] = b - a
                row[key + "_halves_over_err"] = (b - a) / math.hypot(ea, eb)
            except (TypeError, ValueError, ZeroDivisionError):
                row[key + "_halves"] = None
                row[key + "_halves_over_err"] = None
        rows.append(row)
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    md = ["| analysis | frames / samples | Ma inlet rows (mixture mean; paper's sum) | phi inlet rows | Ma, phi rows 2-4 | "
          + " | ".join(name for _, name in DEFINITIONS) + " | phi_peak | shock angle |",
          "|" + "---|" * (7 + len(DEFINITIONS))]
    for row in rows:
        md.append(f"| {row['analysis']} | {row['samples']} | {num(row['Ma_inlet_rows'], 2)} "
                  f"({num(row['Ma_inlet_rows_paper_sum'], 2)}) | {num(row['phi_inlet_rows'], 4)} | "
                  f"{num(row['Ma_rows_2_4'], 2)}, {num(row['phi_rows_2_4'], 4)} | "
                  + " | ".join(pm(row[k], row[k + "_err"]) for k, _ in DEFINITIONS)
                  + f" | {num(row['phi_peak'], 2)} | {num(row['shock_angle_deg'], 1)} deg |")
    md += ["", "Window halves (second half minus first half of the averaging window, delta/D; in "
           "brackets in units of the two halves' combined error):", "",
           "| analysis | " + " | ".join(name for _, name in DEFINITIONS)
           + " | primary: largest change over the 12 analysis cuts |",
           "|" + "---|" * (2 + len(DEFINITIONS))]
    for row in rows:
        cells = []
        for k, _ in DEFINITIONS:
            v, e = row[k + "_halves"], row[k + "_halves_over_err"]
            cells.append("n/a" if v is None else f"{v:+.3f} ({e:+.1f})")
        md.append(f"| {row['analysis']} | " + " | ".join(cells)
                  + f" | {num(row['primary_largest_change_over_D'])} |")
    with open(prefix + ".md", "w") as f:
        f.write("\n".join(md) + "\n")

    # Stagnation line: distance from the cylinder's face in d.
    d = 1e-3
    fig, ax = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    styles = ["-", "--", ":", "-."]
    for (label, r), ls in zip(runs, styles):
        p, pa = r["prof"], r["pattrs"]
        dist = (pa["surface"] - p["y"]) / d
        ok = (p["masked"] == 0) & (dist > 0)
        ax[0].plot(dist[ok], p["phi"][ok], ls, label=label)
        line = ax[1].plot(dist[ok], p["T_norm"][ok], ls, label=label)[0]
        D = r["s"]["detachment_length_m"] / r["s"]["delta_over_D"] if r["s"]["delta_over_D"] else None
        if D:
            for a in ax:
                a.axvline(r["s"]["delta_over_D"] * D / d, color=line.get_color(), ls=ls, lw=0.8)
    ax[0].set_ylabel("phi")
    ax[1].set_ylabel("T / (m U^2)")
    ax[1].set_yscale("log")
    ax[1].set_xlabel("distance from the cylinder's face along the stagnation line (d)")
    ax[0].set_xlim(0, 40)
    ax[1].set_xlim(0, 40)
    ax[0].invert_xaxis()
    ax[0].legend(fontsize=8)
    ax[0].set_title("stagnation line (vertical lines: primary front, T half-rise)", fontsize=9)
    fig.tight_layout()
    fig.savefig(prefix + "_profiles.png", dpi=110)

    fig, ax = plt.subplots(1, 2, figsize=(10, 6), sharey=True)
    for a, (label, r) in zip(ax, runs[:2]):
        g = r["grid"]
        ext = [g["x0"] / d, (g["x0"] + g["nx"] * g["dx"]) / d, g["y0"] / d,
               (g["y0"] + g["ny"] * g["dy"]) / d]
        im = a.imshow(r["phi"], origin="lower", extent=ext, vmin=0, vmax=0.7, cmap="viridis")
        a.set_title(label, fontsize=9)
        a.set_xlabel("x (d)")
        # The neighbourhood of the cylinder: 40 d or 4 D upstream, 80 d or 8 D downstream.
        _, yc, D = (v / d for v in r["obstacle"])
        a.set_ylim(max(ext[2], yc - max(4 * D, 40)), min(ext[3], yc + max(8 * D, 80)))
    ax[0].set_ylabel("y (d), flow upwards")
    fig.colorbar(im, ax=ax, label="phi", shrink=0.8)
    fig.savefig(prefix + "_phi.png", dpi=110)


if __name__ == "__main__":
    main()

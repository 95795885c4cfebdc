#!/usr/bin/python3
"""The detachment length of several runs, like the paper's Fig. 6: delta/D against D/d,
one series per upstream Mach number, with the block-average standard errors as error bars.

Usage: plot_detachment.py DETACHMENT_JSON OUT_PNG

DETACHMENT_JSON is the table `granshock fields DIR... --out OUT` writes
(OUT/detachment.json). Runs are grouped by their target Ma_inf (rounded to 3 significant
digits). Needs matplotlib (Debian: python3-matplotlib).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display

import matplotlib.pyplot as plt  # noqa: E402


def number(value):
    return float("nan") if value is None else float(value)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1]) as f:
        rows = json.load(f)
    groups = {}
    for row in rows:
        ma = number(row["ma_inf_target"])
        key = float(f"{ma:.3g}") if math.isfinite(ma) else float("nan")
        groups.setdefault(key, []).append(row)

    fig, ax = plt.subplots(figsize=(5.5, 4.0), constrained_layout=True)
    markers = "osD^v<>"
    # A run whose delta/D (or D/d) could not be determined has no point; the figure says
    # how many, and detachment.json says why (delta_over_D_reason).
    left_out = 0
    for i, key in enumerate(sorted(groups, key=lambda k: (math.isnan(k), k))):
        usable = [r for r in groups[key]
                  if math.isfinite(number(r["D_over_d"])) and math.isfinite(number(r["delta_over_D"]))]
        left_out += len(groups[key]) - len(usable)
        if not usable:
            continue
        series = sorted(usable, key=lambda r: number(r["D_over_d"]))
        x = [number(r["D_over_d"]) for r in series]
        y = [number(r["delta_over_D"]) for r in series]
        err = [number(r["delta_over_D_err"]) for r in series]
        err = [e if math.isfinite(e) else 0.0 for e in err]
        label = f"Ma$_\\infty$ = {key:g}" if math.isfinite(key) else "Ma$_\\infty$ unknown"
        ax.errorbar(x, y, yerr=err, marker=markers[i % len(markers)], capsize=3, linewidth=1.0, label=label)
    if left_out:
        ax.text(0.98, 0.02, f"{left_out} of {len(rows)} runs without a determinable $\\delta$/D",
                transform=ax.transAxes, ha="right", va="bottom", fontsize=8, color="0.3")
    ax.set_ylim(bottom=0)
    ax.set_xlabel("D / d")
    ax.set_ylabel("$\\delta$ / D")
    ax.set_title("Detachment length", fontsize=10)
    ax.grid(alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8)
    os.makedirs(os.path.dirname(os.path.abspath(sys.argv[2])), exist_ok=True)
    fig.savefig(sys.argv[2], dpi=150)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())

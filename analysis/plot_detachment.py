#!/usr/bin/python3
"""The detachment length of several runs, like the paper's Fig. 6: delta/D against D/d,
one series per upstream Mach number, with the block-average errors as error bars (a point
whose error is undeterminable is drawn open, without a bar); one panel
per definition of the shock front (docs/fields.md, section 6; the fitted fronts with their
thickness as a band, 10-90 % of the rise = 2.2 w about delta/D), and in each Billig's
correlation for the bow-shock stand-off of a cylinder in a perfect gas (gamma = 1.4),
delta/R = 0.386 exp(4.67 / Ma^2) (F. S. Billig, "Shock-wave shapes around spherical- and
cylindrical-nosed bodies", J. Spacecraft Rockets 4 (1967) 822-823), at each Ma_inf.

Usage: plot_detachment.py DETACHMENT_JSON OUT_PNG

DETACHMENT_JSON is the table `granshock fields DIR... --out OUT` writes
(OUT/detachment.json). OUT_PNG is written whole and never through a symbolic link
(figure_files.py). Runs are grouped by their target Ma_inf (rounded to 3 significant
digits). Runs that all share one D/d (a study over e or phi) are placed one per run along
x, named, instead of on one vertical line. Needs matplotlib (Debian: python3-matplotlib).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display

import matplotlib.pyplot as plt  # noqa: E402

from figure_files import FigureDirectory  # noqa: E402


def number(value):
    return float("nan") if value is None else float(value)


def draw_points(ax, x, y, err, marker, color, label):
    """Points with an error bar filled, with caps; points whose error is undeterminable
    (n/a) open, without a bar, so that they do not pass for exact values."""
    with_err = [i for i, e in enumerate(err) if math.isfinite(e)]
    without = [i for i, e in enumerate(err) if not math.isfinite(e)]
    ax.plot(x, y, color=color, linewidth=1.0, label=label, marker=None)
    if with_err:
        ax.errorbar([x[i] for i in with_err], [y[i] for i in with_err],
                    yerr=[err[i] for i in with_err], marker=marker, color=color, capsize=3,
                    linestyle="none")
    if without:
        ax.plot([x[i] for i in without], [y[i] for i in without], marker=marker, color=color,
                markerfacecolor="white", linestyle="none")
    return len(without)


# The fitted fronts (docs/fields.md, "The fitted front"): a tanh step of thickness w,
# whose rise from 10 % to 90 % spans 2.2 w. Fig. 6 shows that span about delta/D as a band.
FITS = ("temperature_fit", "density_fit")
RISE_10_90_OVER_W = 2.0 * math.atanh(0.8)  # 2.197


def draw_thickness(ax, series, x, y, definition, color, label):
    """The band delta/D +- (1.1 w) / D over the points whose w is known; True if drawn."""
    half = [number(r.get(f"w_over_d_{definition}")) * RISE_10_90_OVER_W / 2 / number(r["D_over_d"])
            for r in series]
    keep = [i for i, h in enumerate(half) if math.isfinite(h)]
    if not keep:
        return False
    if len(keep) == 1:  # one run in the series: a bar of the band's height, not a zero-width band
        i = keep[0]
        ax.vlines([x[i]], [y[i] - half[i]], [y[i] + half[i]], color=color, alpha=0.25, linewidth=9,
                  label=label)
        return True
    ax.fill_between([x[i] for i in keep], [y[i] - half[i] for i in keep],
                    [y[i] + half[i] for i in keep], color=color, alpha=0.2, linewidth=0,
                    label=label)
    return True


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

    # Rows of panels: temperature, then density; the fitted fronts in the middle column,
    # each with its thickness as a band.
    definitions = [("temperature_jump", "T half-rise (primary)"),
                   ("temperature_fit", "fitted T front"),
                   ("sonic_line", "sonic point"),
                   ("density_threshold", "$\\phi$ half-way"),
                   ("density_fit", "fitted $\\phi$ front"),
                   ("density_max_gradient", "steepest $\\phi$ rise")]
    fig, axes = plt.subplots(2, 3, figsize=(12.5, 7.0), sharex=True, sharey=True,
                             constrained_layout=True)
    markers = "osD^v<>"
    order = sorted(groups, key=lambda k: (math.isnan(k), k))
    all_x = [number(r["D_over_d"]) for r in rows if math.isfinite(number(r["D_over_d"]))]
    # Runs that share one D/d (a study over e or phi at fixed D/d) would stand on one
    # vertical line: then each run is its own place on the x axis, named by its run.
    one_size = len({round(v, 9) for v in all_x}) == 1 and len(rows) > 1
    names = [str(r.get("run", i)) for i, r in enumerate(rows)]

    def x_of(row):
        return float(rows.index(row)) if one_size else number(row["D_over_d"])
    no_error_bar = 0
    banded = {}  # the panels with a thickness band, which get a legend of their own
    for ax, (definition, title) in zip(axes.flat, definitions):
        key_y = f"delta_over_D_{definition}"
        # Tables before granshock 0.9 have the density threshold only, as delta_over_D.
        if not any(key_y in r for r in rows):
            key_y = "delta_over_D" if definition == "density_threshold" else None
        # A run whose delta/D (or D/d) could not be determined has no point; the panel says
        # how many, and detachment.json says why (delta_over_D_reason).
        left_out = 0
        for i, key in enumerate(order):
            color = f"C{i}"
            if math.isfinite(key) and key > 0 and all_x:
                # Independent of D/d: a line across the panel.
                billig = 0.5 * 0.386 * math.exp(4.67 / key ** 2)
                ax.axhline(billig, color=color, linestyle=":", linewidth=1.0,
                           label=f"Billig, Ma {key:g}")
            if key_y is None:
                continue
            usable = [r for r in groups[key] if math.isfinite(number(r["D_over_d"]))
                      and math.isfinite(number(r.get(key_y)))]
            left_out += len(groups[key]) - len(usable)
            if not usable:
                continue
            series = sorted(usable, key=x_of)
            x = [x_of(r) for r in series]
            y = [number(r[key_y]) for r in series]
            err = [number(r.get(key_y + "_err") if key_y != "delta_over_D" else r["delta_over_D_err"])
                   for r in series]
            label = f"Ma$_\\infty$ = {key:g}" if math.isfinite(key) else "Ma$_\\infty$ unknown"
            no_error_bar += draw_points(ax, x, y, err, markers[i % len(markers)], color, label)
            if definition in FITS and draw_thickness(
                    ax, series, x, y, definition, color,
                    None if banded.get(ax) else "band: 10-90 % of the rise (2.2 w)"):
                banded[ax] = True
        if left_out:
            ax.text(0.98, 0.02, f"{left_out} of {len(rows)} runs without a determinable $\\delta$/D",
                    transform=ax.transAxes, ha="right", va="bottom", fontsize=7, color="0.3")
        if key_y is None:
            ax.text(0.5, 0.5, "not in this table", transform=ax.transAxes, ha="center", color="0.4")
        ax.set_title(f"Detachment length: {title}", fontsize=9)
        ax.grid(alpha=0.3)
    # The panels share their y axis: its range is set once, from every panel's points and
    # bands (set in the loop, it would freeze at the first panel's).
    axes[0, 0].autoscale_view()
    axes[0, 0].set_ylim(0, axes[0, 0].get_ylim()[1])
    for ax in axes[-1]:
        if one_size:
            ax.set_xticks(range(len(rows)))
            ax.set_xticklabels(names, rotation=30, ha="right", fontsize=7)
            ax.set_xlabel(f"run (all at D / d = {all_x[0]:g})")
        else:
            ax.set_xlabel("D / d")
    if no_error_bar:  # named in the legend (a note under the axes would meet their labels)
        axes[0, 0].plot([], [], marker="o", color="0.4", markerfacecolor="white",
                        linestyle="none", label="open: no error bar (n/a)")
    for ax in axes[:, 0]:
        ax.set_ylabel("$\\delta$ / D")
    if axes[0, 0].get_legend_handles_labels()[0]:
        axes[0, 0].legend(fontsize=7)
    for ax in banded:  # the band only: the series are named in the first panel
        handles, labels = ax.get_legend_handles_labels()
        ax.legend([h for h, t in zip(handles, labels) if t.startswith("band:")],
                  [t for t in labels if t.startswith("band:")], fontsize=7)
    directory, name = os.path.split(os.path.abspath(sys.argv[2]))
    with FigureDirectory(directory) as figures:
        figures.save(fig, name, dpi=150)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())

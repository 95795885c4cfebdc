#!/usr/bin/python3
"""The figures of a granshock study (docs/study.md, "Figures"): for each axis, the
detachment length delta/D (with its block error; a point without one is drawn open), the
peak solid fraction phi_peak and the measured upstream Mach number Ma_inf (with its target)
against the axis value, one PNG per axis; a case whose window is not yet steady is crossed.

Usage: plot_study.py STUDY_JSON FIGURES_DIR MODE AXIS [AXIS ...]

STUDY_JSON is the table `granshock study` writes (OUT/study.json); MODE is the study's
(product, list or sweep). In a product, each combination of the other axes' values is a
series; otherwise an axis is one series. Axis values that are all numbers make a numeric
x axis, others are placed in study order. Finished cases only; a case whose number could not
be determined (null, with its _reason in the table) has no point. Needs matplotlib (Debian:
python3-matplotlib).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display

import matplotlib.pyplot as plt  # noqa: E402

PANELS = [
    ("delta_over_D", "delta_over_D_err", "$\\delta$ / D"),
    ("phi_peak", None, "$\\phi_{peak}$"),
    ("ma_inf_measured", None, "Ma$_\\infty$ measured"),
]


def number(value):
    return float("nan") if value is None or isinstance(value, (str, bool)) else float(value)


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def series_of(rows, axis, axes, mode):
    """Rows grouped into series: by the other axes' values in a product, else one series."""
    groups = {}
    for row in rows:
        if mode == "product":
            key = tuple((a, row.get("axis." + a)) for a in axes if a != axis)
        else:
            key = ()
        groups.setdefault(key, []).append(row)
    return groups


def series_label(key):
    return ", ".join(f"{a} = {v}" for a, v in key) if key else None


def plot_axis(rows, axis, axes, mode, png):
    column = "axis." + axis
    on_axis = [r for r in rows if r.get(column) is not None]
    finished = [r for r in on_axis if r["status"] == "finished"]
    numeric = all(is_number(r[column]) for r in on_axis)
    categories = []
    for r in on_axis:
        if r[column] not in categories:
            categories.append(r[column])

    def x_of(row):
        return float(row[column]) if numeric else float(categories.index(row[column]))

    fig, panels = plt.subplots(1, len(PANELS), figsize=(4.0 * len(PANELS), 3.6), sharex=True,
                               constrained_layout=True)
    markers = "osD^v<>"
    groups = series_of(finished, axis, axes, mode)
    for panel, (key, err_key, label) in zip(panels, PANELS):
        drawn = no_error_bar = not_steady = 0
        for i, (group, members) in enumerate(sorted(groups.items(), key=lambda g: str(g[0]))):
            points = sorted((r for r in members if math.isfinite(number(r.get(key)))), key=x_of)
            if not points:
                continue
            x = [x_of(r) for r in points]
            y = [number(r[key]) for r in points]
            marker = markers[i % len(markers)]
            line = panel.plot(x, y, marker=marker, linewidth=1.0, label=series_label(group))[0]
            if err_key:
                # A point with an error gets its bar; one whose error is undeterminable (n/a)
                # is drawn open, so that it does not pass for an exact value.
                err = [number(r.get(err_key)) for r in points]
                bars = [k for k, e in enumerate(err) if math.isfinite(e)]
                if bars:
                    panel.errorbar([x[k] for k in bars], [y[k] for k in bars],
                                   yerr=[err[k] for k in bars], color=line.get_color(),
                                   marker="none", linestyle="none", capsize=3)
                open_points = [k for k, e in enumerate(err) if not math.isfinite(e)]
                if open_points:
                    panel.plot([x[k] for k in open_points], [y[k] for k in open_points],
                               marker=marker, color=line.get_color(), markerfacecolor="white",
                               linestyle="none")
                    no_error_bar += len(open_points)
            # A case whose window is not yet steady (docs/fields.md, section 12) is crossed.
            unsteady = [k for k, r in enumerate(points) if r.get("steady") is False]
            if unsteady:
                panel.scatter([x[k] for k in unsteady], [y[k] for k in unsteady], marker="x",
                              s=60, color="k", zorder=4)
                not_steady += len(unsteady)
            drawn += len(points)
        if key == "ma_inf_measured":
            targets = [r for r in finished if math.isfinite(number(r.get("ma_inf_target")))]
            if targets:
                panel.scatter([x_of(r) for r in targets], [number(r["ma_inf_target"]) for r in targets],
                              marker="_", s=200, color="0.4", label="target", zorder=3)
        if drawn < len(finished):
            panel.text(0.98, 0.02, f"{len(finished) - drawn} of {len(finished)} finished cases "
                       "without a value", transform=panel.transAxes, ha="right", va="bottom",
                       fontsize=7, color="0.3")
        if not finished:
            panel.text(0.5, 0.5, "no finished case yet", transform=panel.transAxes,
                       ha="center", va="center", color="0.3")
        panel.set_xlabel(axis)
        panel.set_ylabel(label)
        panel.grid(alpha=0.3)
        if not numeric:
            panel.set_xticks(range(len(categories)))
            panel.set_xticklabels([str(c) for c in categories], rotation=30, ha="right", fontsize=8)
        if no_error_bar:
            panel.plot([], [], marker="o", color="0.4", markerfacecolor="white", linestyle="none",
                       label="open: no error bar (n/a)")
        if not_steady:
            panel.scatter([], [], marker="x", color="k", label="x: not yet steady")
        handles, labels = panel.get_legend_handles_labels()
        if any(labels):
            panel.legend(fontsize=7)
    fig.suptitle(f"{axis}: {len(finished)} of {len(on_axis)} cases finished", fontsize=10)
    temporary = png + ".tmp.png"
    fig.savefig(temporary, dpi=150)
    plt.close(fig)
    os.replace(temporary, png)


def main():
    if len(sys.argv) < 5:
        print(__doc__, file=sys.stderr)
        return 2
    table, figures, mode, axes = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    with open(table) as f:
        rows = json.load(f)
    os.makedirs(figures, exist_ok=True)
    for axis in axes:
        plot_axis(rows, axis, axes, mode, os.path.join(figures, axis + ".png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())

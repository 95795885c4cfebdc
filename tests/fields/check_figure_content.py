#!/usr/bin/python3
"""Checks what the figures of plot_fields.py say (docs/fields.md, "figures/"), drawing
them once without writing them:

- mach.png and solid_fraction.png name each front they draw by its definition, the
  primary one (T half-rise, what delta/D measures) among them;
- the Mach colour bar has a tick at 1 (the sonic value, where its colours turn);
- no text of a field figure overlaps its x-axis label;
- stagnation_profiles.png shows the fronts and the surface away from the axis' ends.

Usage: check_figure_content.py FIELDS_H5 SCRIPT_DIR
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.text  # noqa: E402
import numpy as np  # noqa: E402


class Captured:
    """Stands for figure_files.FigureDirectory: keeps each figure instead of writing it."""

    def __init__(self):
        self.figures = {}

    def save(self, fig, name, **_):
        self.figures[name] = fig


def overlapping_x_label(fig):
    renderer = fig.canvas.get_renderer()
    ax = fig.axes[0]
    label = ax.xaxis.label.get_window_extent(renderer)
    found = []
    for text in fig.findobj(matplotlib.text.Text):
        if text is ax.xaxis.label or not text.get_visible() or not text.get_text().strip():
            continue
        if text.get_window_extent(renderer).overlaps(label):
            found.append(text.get_text())
    return found


def main():
    fields_h5, script_dir = sys.argv[1], sys.argv[2]
    sys.path.insert(0, script_dir)
    import plot_fields  # noqa: E402

    run = plot_fields.Run(fields_h5)
    out = Captured()
    plot_fields.draw_figures(run, out)
    failures = []
    for name in ("mach.png", "solid_fraction.png"):
        fig = out.figures[name]
        fig.canvas.draw()
        legend = fig.axes[0].get_legend()
        texts = [t.get_text() for t in legend.get_texts()] if legend else []
        if not any("T half-rise (primary" in t for t in texts):
            failures.append(f"{name}: no primary (T half-rise) front in the legend: {texts}")
        if not any("half-way" in t and "angle fit" in t for t in texts):
            failures.append(f"{name}: the density front is not named by its definition: {texts}")
        if any(t == "shock front" for t in texts):
            failures.append(f"{name}: a front without its definition: {texts}")
        overlaps = overlapping_x_label(fig)
        if overlaps:
            failures.append(f"{name}: text over the x-axis label: {overlaps}")
    ticks = out.figures["mach.png"].axes[1].get_yticks()
    if not np.any(np.isclose(ticks, 1.0)):
        failures.append(f"mach.png: no colour-bar tick at Ma = 1: {list(ticks)}")

    profile = out.figures["stagnation_profiles.png"].axes[-1]
    lo, hi = profile.get_xlim()
    fronts = [y for y in run.fronts.values() if np.isfinite(y)]
    if fronts and np.isfinite(run.surface):
        for y in fronts + [run.surface]:
            if not lo < y < hi:
                failures.append(f"stagnation_profiles.png: {y:.3g} d outside the axis [{lo:.3g}, {hi:.3g}]")
        share = (min(fronts) - lo) / (hi - lo)
        if share > 0.85:
            failures.append(f"stagnation_profiles.png: the first front at {share:.0%} of the axis")
    for message in failures:
        print(f"{fields_h5}: {message}", file=sys.stderr)
    print(f"{fields_h5}: figure content {'FAILED' if failures else 'as documented'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

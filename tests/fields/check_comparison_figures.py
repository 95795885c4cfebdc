#!/usr/bin/python3
"""Checks the figures that compare runs (docs/fields.md "figures/", docs/study.md
"Figures"), drawn once from a made-up table of four runs at one D/d, one of them without
an error bar and one not yet steady:

- Fig. 6 (plot_detachment.py) places runs that share one D/d one per run along x, not on
  one vertical line;
- both it and a study's axis figure (plot_study.py) draw the point without an error bar
  open, and name that in the legend; the study figure crosses the unsteady case.

Usage: check_comparison_figures.py SOURCE_DIR
"""
import json
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DRAWN = []
_close = plt.close


def keep_and_close(fig=None):
    DRAWN.append(fig)
    _close(fig)


def open_points(fig):
    """(x, y) of the markers drawn open (white face) in every axes of fig."""
    found = []
    for ax in fig.axes:
        for line in ax.get_lines():
            if line.get_marker() not in (None, "None", "none", "") and \
                    line.get_markerfacecolor() in ("white", "w", (1.0, 1.0, 1.0, 1.0)):
                found += list(zip(line.get_xdata(), line.get_ydata()))
    return found


def legend_texts(fig):
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]


def main():
    source = sys.argv[1]
    sys.path[:0] = [os.path.join(source, "analysis"), os.path.join(source, "cases", "study")]
    plt.close = keep_and_close
    import plot_detachment  # noqa: E402
    import plot_study  # noqa: E402

    failures = []
    cases = [(0.3, 0.02, True), (0.5, None, True), (0.7, 0.03, False), (0.9, 0.01, True)]
    with tempfile.TemporaryDirectory() as tmp:
        rows = []
        for i, (e, err, _) in enumerate(cases):
            row = {"run": f"runs/e-{e}", "D_over_d": 20.0, "ma_inf_target": 5.9,
                   "delta_over_D": 0.2 + 0.02 * i, "delta_over_D_err": err}
            for d in ("temperature_jump", "density_threshold", "density_max_gradient",
                      "sonic_line"):
                row[f"delta_over_D_{d}"], row[f"delta_over_D_{d}_err"] = 0.2 + 0.02 * i, err
            rows.append(row)
        with open(os.path.join(tmp, "detachment.json"), "w") as f:
            json.dump(rows, f)
        sys.argv = ["plot_detachment.py", os.path.join(tmp, "detachment.json"),
                    os.path.join(tmp, "detachment_length.png")]
        plot_detachment.main()
        fig6 = DRAWN[-1]
        xs = {round(float(x), 9) for line in fig6.axes[0].get_lines()
              if line.get_marker() not in (None, "None", "none", "") for x in line.get_xdata()}
        if len(xs) < 4:
            failures.append(f"Fig. 6: four runs at one D/d drawn at x = {sorted(xs)}")
        if (1.0, 0.22) not in [(round(float(x), 6), round(float(y), 6)) for x, y in open_points(fig6)]:
            failures.append(f"Fig. 6: the run without an error bar is not drawn open: {open_points(fig6)}")
        if "open: no error bar (n/a)" not in legend_texts(fig6):
            failures.append(f"Fig. 6: legend {legend_texts(fig6)}")

        study = [{"status": "finished", "axis.e": e, "delta_over_D": 0.2 + 0.02 * i,
                  "delta_over_D_err": err, "phi_peak": 0.5, "ma_inf_measured": 6.0,
                  "ma_inf_target": 5.9, "steady": steady}
                 for i, (e, err, steady) in enumerate(cases)]
        with open(os.path.join(tmp, "study.json"), "w") as f:
            json.dump(study, f)
        plot_study.plot_axis(study, "e", ["e"], "list", os.path.join(tmp, "e.png"))
        axis_fig = DRAWN[-1]
        if (0.5, 0.22) not in [(round(float(x), 6), round(float(y), 6)) for x, y in open_points(axis_fig)]:
            failures.append(f"study figure: the case without an error bar is not open: {open_points(axis_fig)}")
        texts = legend_texts(axis_fig)
        for wanted in ("open: no error bar (n/a)", "x: not yet steady"):
            if wanted not in texts:
                failures.append(f"study figure: no '{wanted}' in the legend {texts}")
    for message in failures:
        print(message, file=sys.stderr)
    print("comparison figures:", "FAILED" if failures else "as documented")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

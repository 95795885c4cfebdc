#!/usr/bin/python3
"""Checks the figures that compare runs (docs/fields.md "figures/", docs/study.md
"Figures"), drawn once from a made-up table of four runs at one D/d, one of them without
an error bar and one not yet steady:

- Fig. 6 (plot_detachment.py) places runs that share one D/d one per run along x, not on
  one vertical line;
- Fig. 6 draws each fitted front's thickness as a band of 10-90 % of its rise (2.2 w)
  about delta/D, over the runs whose w is known, a bar for a series of one run, and its
  shared y axis holds the highest band (a second made-up table: D/d = 10, 50, 100);
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


def draw_fig6(plot_detachment, tmp, name, rows):
    """Fig. 6 of `rows` (detachment.json's rows) through plot_detachment.py; the figure."""
    with open(os.path.join(tmp, name + ".json"), "w") as f:
        json.dump(rows, f)
    sys.argv = ["plot_detachment.py", os.path.join(tmp, name + ".json"),
                os.path.join(tmp, name + ".png")]
    plot_detachment.main()
    return DRAWN[-1]


def thickness_band(plot_detachment, tmp):
    """Draws Fig. 6 from three runs at D/d = 10, 50, 100 with fitted T fronts of w = 1, 2 d
    and unknown; returns {x: half-width of the band} of the fitted T panel, or None."""
    rows = []
    for d_over_d, delta, w, ma in [(10.0, 0.40, 1.0, 5.9), (50.0, 0.17, 2.0, 5.9),
                                   (100.0, 0.14, None, 5.9), (10.0, 0.45, 1.5, 2.64)]:
        row = {"run": f"runs/d{d_over_d:g}", "D_over_d": d_over_d, "ma_inf_target": ma,
               "delta_over_D": delta, "delta_over_D_err": 0.01,
               "w_over_d_temperature_fit": w, "w_over_d_temperature_fit_err": 0.1}
        for d in ("temperature_jump", "temperature_fit", "density_threshold", "density_fit",
                  "density_max_gradient", "sonic_line"):
            row[f"delta_over_D_{d}"], row[f"delta_over_D_{d}_err"] = delta, 0.01
        rows.append(row)
    fig = draw_fig6(plot_detachment, tmp, "fits", rows)
    panel = [ax for ax in fig.axes if "fitted T" in ax.get_title()]
    polygons = [c for ax in panel for c in ax.collections if type(c).__name__ == "PolyCollection"]
    if not polygons:
        return None
    halves = {}
    for x, y in polygons[0].get_paths()[0].vertices:
        halves.setdefault(round(float(x), 9), []).append(float(y))
    bands = {x: (max(ys) - min(ys)) / 2 for x, ys in halves.items()}
    # The Ma 2.64 series has one run: its band is a bar (a LineCollection of one segment).
    bars = [seg for ax in panel for c in ax.collections if type(c).__name__ == "LineCollection"
            and c.get_alpha() == 0.25 for seg in c.get_segments()]
    bands["bar"] = [abs(seg[1][1] - seg[0][1]) / 2 for seg in bars]
    bands["top"] = panel[0].get_ylim()[1]  # the shared y axis must hold the highest band
    return bands


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
        fig6 = draw_fig6(plot_detachment, tmp, "detachment", rows)
        xs = {round(float(x), 9) for line in fig6.axes[0].get_lines()
              if line.get_marker() not in (None, "None", "none", "") for x in line.get_xdata()}
        if len(xs) < 4:
            failures.append(f"Fig. 6: four runs at one D/d drawn at x = {sorted(xs)}")
        if (1.0, 0.22) not in [(round(float(x), 6), round(float(y), 6)) for x, y in open_points(fig6)]:
            failures.append(f"Fig. 6: the run without an error bar is not drawn open: {open_points(fig6)}")
        if "open: no error bar (n/a)" not in legend_texts(fig6):
            failures.append(f"Fig. 6: legend {legend_texts(fig6)}")

        bands = thickness_band(plot_detachment, tmp)
        if bands is None:
            failures.append("Fig. 6: no thickness band in the fitted T panel")
        else:
            for x, half in [(10.0, 1.0 * 2.1972 / 2 / 10), (50.0, 2.0 * 2.1972 / 2 / 50)]:
                got = bands.get(x)
                if got is None or abs(got - half) > 1e-4:
                    failures.append(f"Fig. 6: band half-width at D/d = {x:g} is {got}, not {half:.5f}")
            if [round(h, 5) for h in bands["bar"]] != [round(1.5 * 2.1972 / 2 / 10, 5)]:
                failures.append(f"Fig. 6: the one-run series' bar half-heights {bands['bar']}")
            if bands["top"] < 0.45 + 1.5 * 2.1972 / 2 / 10:
                failures.append(f"Fig. 6: the y axis ends at {bands['top']:.3f}, below the bands")
            if 100.0 in bands:
                failures.append("Fig. 6: a band drawn at D/d = 100, whose w is unknown")
            if "band: 10-90 % of the rise (2.2 w)" not in legend_texts(DRAWN[-1]):
                failures.append(f"Fig. 6: band not in a legend {legend_texts(DRAWN[-1])}")

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

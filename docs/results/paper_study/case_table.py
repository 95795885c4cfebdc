#!/usr/bin/python3
"""The nine-case table of README.md from a study directory's study.csv.

Usage: /usr/bin/python3 case_table.py STUDY_DIR/study.csv
"""
import csv
import sys

DEFINITIONS = ["temperature_jump", "sonic_line", "density_threshold", "density_max_gradient"]


def delta(row, definition):
    value = row[f"detachment.{definition}.delta_over_D"]
    err = row[f"detachment.{definition}.delta_over_D_err"]
    if not value:
        return "n/a"
    return f"{float(value):.3f} +- {float(err):.3f}" if err else f"{float(value):.3f}"


def main(path):
    rows = list(csv.DictReader(open(path)))
    print("| case | D/d | Ma_inf target / measured (inlet) | delta/D: T half-rise (primary) "
          "| sonic point | phi half-way | steepest rise | primary consistent across cuts "
          "| phi_peak | shock angle | wall time |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: (float(r["scene.mach"]), float(r["scene.D_over_d"]))):
        d_over_d = float(r["scene.D_over_d"])
        verdict = "detachment_convergence.verdicts.temperature_jump."
        change = r[verdict + "max_deviation_over_D"]
        change = f"{float(change) * d_over_d:.2f} d" if change else "n/a"
        cells = [r["case"], f"{d_over_d:g}",
                 f"{float(r['scene.mach']):g} / {float(r['ma_inf_measured']):.2f}"]
        cells += [delta(r, k) for k in DEFINITIONS]
        cells += [f"{r[verdict + 'consistent']} (largest change {change})",
                  f"{float(r['phi_peak']):.2f}", f"{float(r['shock_angle_deg']):.1f} deg",
                  f"{float(r['wall_seconds']):.0f} s"]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1])

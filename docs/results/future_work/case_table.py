#!/usr/bin/python3
"""The case table of README.md from the study's study.csv.

Usage: /usr/bin/python3 case_table.py STUDY_DIR/study.csv
"""
import csv
import sys


def delta(row, definition):
    value = row[f"detachment.{definition}.delta_over_D"]
    err = row[f"detachment.{definition}.delta_over_D_err"]
    return f"{float(value):.3f} ± {float(err):.3f}" if value else "n/a"


def number(row, key, digits):
    return f"{float(row[key]):.{digits}f}" if row[key] else "n/a"


def main(path):
    rows = list(csv.DictReader(open(path)))
    print("| case | delta/D T-jump (primary) | density half-way | sonic line | consistent "
          "| phi_peak | shock-layer phi | Ma_inf measured | shock angle (deg) | wall (s) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        cells = [r["case"]] + [delta(r, k) for k in
                               ("temperature_jump", "density_threshold", "sonic_line")]
        cells += [r["detachment_convergence.verdicts.temperature_jump.consistent"],
                  number(r, "phi_peak", 3), number(r, "shock_layer_phi_mean", 3),
                  number(r, "ma_inf_measured", 2), number(r, "shock_angle_deg", 1),
                  f"{float(r['wall_seconds']):.0f}"]
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1])

#!/usr/bin/python3
"""The tables of README.md from the cases' summary.json files: each full-length case
against its 2 s run of ../paper_study (study.csv there); with --figure, Fig. 6 of the cases
here (analysis/plot_detachment.py, from their summary.json files: the fields.h5 files that
`granshock study --collect` would re-analyse are not kept).

Usage: /usr/bin/python3 full_table.py [DIR] [--figure OUT.png]
  (DIR: this folder, holding CASE/summary.json)
"""
import csv
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
SHORT_STUDY = HERE.parent / "paper_study" / "study.csv"
DEFINITIONS = [("temperature_jump", "T half-rise (primary)"), ("temperature_fit", "fitted T"),
               ("sonic_line", "sonic point"), ("density_threshold", "phi half-way"),
               ("density_fit", "fitted phi")]


def pm(value, err, digits=3):
    if value is None:
        return "no front"
    return f"{value:.{digits}f} +- {err:.{digits}f}" if err is not None else f"{value:.{digits}f}"


def load_cases(folder):
    cases = []
    for path in sorted(folder.glob("*/summary.json")):
        s = json.load(open(path))
        d_over_d = float(re.match(r"d(\d+)_", path.parent.name).group(1))  # d10_u1000: D = 10 d
        cases.append((path.parent.name, s, d_over_d, float(s["ma_inf_target"])))
    return sorted(cases, key=lambda c: (c[3], c[2]))


def short_runs():
    if not SHORT_STUDY.exists():
        return {}
    return {r["case"]: r for r in csv.DictReader(open(SHORT_STUDY))}


def main(folder):
    cases = load_cases(folder)
    short = short_runs()

    print("| case | D/d | Ma_inf target / inlet | " +
          " | ".join(name for _, name in DEFINITIONS) +
          " | w/d (T fit) | w/d (phi fit) | phi_peak | steady (window halves) |")
    print("|---" * (7 + len(DEFINITIONS)) + "|")
    for name, s, d_over_d, mach in cases:
        det = s["detachment"]
        cells = [name, f"{d_over_d:g}", f"{mach:g} / {s['ma_inf_measured']:.2f}"]
        cells += [pm(det[k].get("delta_over_D"), det[k].get("delta_over_D_err")) for k, _ in DEFINITIONS]
        for fit in ("temperature_fit", "density_fit"):
            w = det[fit].get("w_over_d")
            cells.append(pm(w, det[fit].get("w_over_d_err"), 2) if w is not None else "n/a")
        cells.append(f"{s['phi_peak']:.2f}")
        halves = s["steadiness"]["delta_over_D_halves"]
        cells.append(f"{'yes' if halves['steady'] else 'no'} ({halves['first_half']:.3f} / "
                     f"{halves['second_half']:.3f})")
        print("| " + " | ".join(cells) + " |")

    print()
    print("| case | T half-rise 2 s | 5 s | change / combined error | T half-rise across the "
          "cuts | fitted T across the cuts | "
          "wall time | particle-steps/s | backend, threads |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, s, d_over_d, mach in cases:
        det = s["detachment"]["temperature_jump"]
        row = short.get(name)
        if row and row["detachment.temperature_jump.delta_over_D"]:
            v2 = float(row["detachment.temperature_jump.delta_over_D"])
            e2 = float(row["detachment.temperature_jump.delta_over_D_err"])
            change = (det["delta_over_D"] - v2) / math.hypot(e2, det["delta_over_D_err"])
            short_cells = [pm(v2, e2), pm(det["delta_over_D"], det["delta_over_D_err"]),
                           f"{change:+.2f}"]
        else:
            short_cells = ["n/a", pm(det.get("delta_over_D"), det.get("delta_over_D_err")), "n/a"]
        verdicts = s["detachment_convergence"]["verdicts"]
        cuts = len(s["detachment_convergence"]["choices"])  # rows, strips, grid, halves
        verdict_cells = [verdict_cell(verdicts[k], d_over_d, cuts)
                         for k in ("temperature_jump", "temperature_fit")]
        print("| " + " | ".join([name] + short_cells + verdict_cells + [
            f"{s['wall_seconds']:.0f} s", f"{s['particle_steps_per_second']:.3g}",
            f"{s['backend']}, {s['threads']}"]) + " |")
    print()
    print_counts(cases)


def failing_cuts(verdict):
    """(cuts moved beyond two errors, cuts without a front) of one verdict. Its text lists
    the failing cuts, "; "-separated (docs/fields.md, "Convergence table")."""
    if verdict["consistent"]:
        return 0, 0
    items = verdict["text"].split(": ", 1)[1].split("; ")
    missing = sum("no front" in item for item in items)
    return len(items) - missing, missing


def no_primary_front(verdict):
    return verdict["text"].startswith("no delta at the reference cut")


def verdict_cell(verdict, d_over_d, cuts):
    if no_primary_front(verdict):
        return "no front at the primary cut"
    moved, missing = failing_cuts(verdict)
    deviation = verdict["max_deviation_over_D"]  # null: no cut found a front to compare
    change = (f"largest change {deviation * d_over_d:.2f} d" if deviation is not None
              else "no cut to compare")
    if verdict["consistent"]:
        return f"true ({change})"
    return f"false: {moved} of {cuts - 1} cuts beyond two errors, {missing} without a front ({change})"


def print_counts(cases):
    """Per definition, over the cases: how many agree with themselves across every cut,
    how many move beyond two errors on no cut where a front is found, and the largest
    change over the cuts in particle diameters."""
    print("| definition | consistent across every cut | no cut beyond two errors where a front "
          "is found | no front at the primary cut | largest change over the cuts (d), "
          "smallest - largest case |")
    print("|---|---|---|---|---|")
    n = len(cases)
    for key, label in DEFINITIONS:
        consistent = agree = no_primary = 0
        changes = []
        for name, s, d_over_d, mach in cases:
            verdict = s["detachment_convergence"]["verdicts"][key]
            if no_primary_front(verdict):
                no_primary += 1
                continue
            consistent += bool(verdict["consistent"])
            agree += failing_cuts(verdict)[0] == 0
            if verdict["max_deviation_over_D"] is not None:
                changes.append(verdict["max_deviation_over_D"] * d_over_d)
        spread = f"{min(changes):.2f} - {max(changes):.2f}" if changes else "n/a"
        print(f"| {label} | {consistent} of {n} | {agree} of {n} | {no_primary} | {spread} |")


def figure(folder, png):
    """Fig. 6 from the cases' summary.json: the rows of detachment.json that
    plot_detachment.py reads (docs/fields.md, "figures/")."""
    rows = []
    for name, s, d_over_d, mach in load_cases(folder):
        row = {"run": name, "D_over_d": d_over_d, "ma_inf_target": mach,
               "delta_over_D": s["delta_over_D"], "delta_over_D_err": s["delta_over_D_err"]}
        for definition, d in s["detachment"].items():
            row[f"delta_over_D_{definition}"] = d.get("delta_over_D")
            row[f"delta_over_D_{definition}_err"] = d.get("delta_over_D_err")
            if "w_over_d" in d:
                row[f"w_over_d_{definition}"] = d["w_over_d"]
                row[f"w_over_d_{definition}_err"] = d.get("w_over_d_err")
        rows.append(row)
    with tempfile.TemporaryDirectory() as tmp:
        table = Path(tmp) / "detachment.json"
        table.write_text(json.dumps(rows))
        script = HERE.parents[2] / "analysis" / "plot_detachment.py"
        subprocess.run(["/usr/bin/python3", str(script), str(table), str(Path(png).resolve())],
                       check=True)


if __name__ == "__main__":
    args = sys.argv[1:]
    png = None
    if "--figure" in args:
        png = args[args.index("--figure") + 1]
        del args[args.index("--figure"):args.index("--figure") + 2]
    folder = Path(args[0]) if args else HERE
    main(folder)
    if png:
        figure(folder, png)

#!/usr/bin/python3
"""A trade table checked on other scenes: the transfer checks of docs/accuracy.md ("Transfer
checks"), which widen where its certificate holds.

Usage: /usr/bin/python3 transfer_table.py BASE_RECORDS OUT_DIR TRANSFER_RECORDS [...]
       [--no-figures]

Each folder holds a study's case records (docs/study.md, "Campaign records"): the base
table's scene and each transfer scene with its own reference and seeds of the scene as
given. Every table is made as trade_table.py makes it; then each setting of the base
table is bounded on every scene by that scene's own certificate (its difference from its
own reference plus k times its own noise), and its bound is the largest of them: a
setting a transfer scene did not run is unbounded. The certified range spans every
scene's D/d and Ma_inf. Writes OUT_DIR/trade.json (the base table's cases with those
bounds, each scene's bound in `bound_on`, and the transfer tables under "transfers",
which `granshock run --accuracy` bounds again the same way: cases/accuracy/accuracy_table.cpp),
trade.csv, trade.md and pareto.png.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import trade_table  # noqa: E402


def span(ranges):
    out = {"D_over_d": [min(r["D_over_d"][0] for r in ranges), max(r["D_over_d"][1] for r in ranges)],
           "mach": [min(r["mach"][0] for r in ranges), max(r["mach"][1] for r in ranges)],
           "shown_on": [name for r in ranges for name in r["shown_on"]]}
    return out


def main(base, out_dir, transfers, figures=True):
    rows, noise, noise_from, title, extra = trade_table.build_table(base)
    if "certified_range" not in extra:
        sys.exit(f"{base}: no study.csv with the reference's D/d and Ma_inf beside the records")
    ranges, checks = [extra["certified_range"]], []
    for folder in transfers:
        t_rows, t_noise, t_from, t_title, t_extra = trade_table.build_table(folder)
        if "certified_range" not in t_extra:
            sys.exit(f"{folder}: no study.csv with the reference's D/d and Ma_inf beside the records")
        ranges.append(t_extra["certified_range"])
        checks.append({"shown_on": t_title, "certified_range": t_extra["certified_range"],
                       "noise": t_noise, "noise_from": t_from,
                       "noise_seeds": t_extra["noise_seeds"],
                       "certificate": t_extra["certificate"],
                       "noise_floor": t_extra["noise_floor"], "cases": t_rows})
    for row in rows:
        bound, by = row["bound"], row["bound_by"]
        row["bound_on"] = {title: bound}
        for check in checks:
            match = next((r for r in check["cases"] if r["case"] == row["case"]), None)
            b, b_by = (None, "not measured") if match is None else (match["bound"], match["bound_by"])
            row["bound_on"][check["shown_on"]] = b
            if bound is not None and (b is None or b > bound):
                bound, by = b, f"{b_by} on {check['shown_on']}"
        row["bound"], row["bound_by"] = bound, by
    floors = [extra["noise_floor"]] + [c["noise_floor"] for c in checks]
    extra["noise_floor"] = max(floors, key=lambda f: f["bound"])
    extra["noise_seeds"] = min([extra["noise_seeds"]] + [c["noise_seeds"] for c in checks])
    extra["certified_range"] = span(ranges)
    extra["transfers"] = checks
    trade_table.write_tables(rows, noise, out_dir, noise_from, extra)
    if figures:
        trade_table.write_figure(rows, noise, title, out_dir)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--no-figures"]
    if len(args) < 3:
        sys.exit("usage: transfer_table.py BASE_RECORDS OUT_DIR TRANSFER_RECORDS [...] [--no-figures]")
    main(args[0], args[1], args[2:], figures="--no-figures" not in sys.argv[1:])

#!/usr/bin/python3
"""The table of docs/results/three_d/README.md, built from the cases' summary.json records.

Usage: /usr/bin/python3 table.py   (run in this directory)
Each case directory under cases/ holds the summary.json of one run. The 3-D phi is a volume
fraction; for a layer of thickness h it is shown beside the 2-D area fraction as the
projected area fraction phi_3d * (3/2) h / d (the same particles seen from above).
"""
import json
import math
import pathlib
import statistics

HERE = pathlib.Path(__file__).resolve().parent
D = 1e-3  # the scenes' particle diameter, m


def load(name):
    return json.loads((HERE / "cases" / name / "summary.json").read_text())


def row(name):
    s = load(name)
    dim = s["dimension"]
    h = 1 if dim == 2 else int(name.split("_h")[1][0]) if "_h" in name else None
    phi_peak = s.get("phi_peak")
    if dim == 3 and not h:  # the sphere: no layer to project
        projected = None
    else:
        projected = phi_peak * 1.5 * h if (dim == 3 and phi_peak is not None) else phi_peak
    return {
        "case": name,
        "dim": dim,
        "h_over_d": h,
        "delta_over_D": s.get("delta_over_D"),
        "err": s.get("delta_over_D_err"),
        "phi_peak": phi_peak,
        "phi_peak_projected": projected,
        "ma_inf_measured": s.get("ma_inf_measured"),
        "shock_angle_deg": s.get("shock_angle_deg"),
        "particles_final": s.get("particles_final"),
        "steps": s.get("steps"),
        "wall_seconds": s.get("wall_seconds"),
    }


def fmt(x, f="{:.3f}"):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f.format(x)


def main():
    names = sorted(p.name for p in (HERE / "cases").iterdir() if (p / "summary.json").exists())
    rows = [row(n) for n in names]
    print("| case | dim | h/d | delta/D +- error | phi_peak (3-D: volume) | phi_peak projected | "
          "Ma_inf at the inlet | shock angle (deg) | particles | steps |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['case']} | {r['dim']} | {r['h_over_d'] or 'n/a'} | {fmt(r['delta_over_D'])} +- "
              f"{fmt(r['err'])} | {fmt(r['phi_peak'])} | {fmt(r['phi_peak_projected'])} | "
              f"{fmt(r['ma_inf_measured'], '{:.2f}')} | {fmt(r['shock_angle_deg'], '{:.1f}')} | "
              f"{r['particles_final']} | {r['steps']} |")
    print()
    groups = {}
    for r in rows:
        key = (r["dim"], r["h_over_d"]) if r["case"].startswith(("slab", "default")) else None
        if key and r["delta_over_D"] is not None:
            groups.setdefault(key, []).append(r)
    print("| group | runs | delta/D mean | std over seeds | phi_peak projected mean | Ma_inf mean |")
    print("|---|---|---|---|---|---|")
    for (dim, h), rs in sorted(groups.items()):
        deltas = [r["delta_over_D"] for r in rs]
        std = statistics.stdev(deltas) if len(deltas) > 1 else float("nan")
        label = "2-D default" if dim == 2 else f"3-D slab h = {h} d"
        print(f"| {label} | {len(rs)} | {statistics.mean(deltas):.3f} | {fmt(std)} | "
              f"{statistics.mean(r['phi_peak_projected'] for r in rs):.3f} | "
              f"{statistics.mean(r['ma_inf_measured'] for r in rs):.2f} |")


if __name__ == "__main__":
    main()

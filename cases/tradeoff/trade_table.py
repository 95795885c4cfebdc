#!/usr/bin/python3
"""The speed-against-accuracy table of `granshock tradeoff` (docs/accuracy.md).

Usage: /usr/bin/python3 trade_table.py STUDY_DIR OUT_DIR [--no-figures] (granshock tradeoff
runs it; --no-figures: the tables without pareto.png)

Every case is compared with the case "reference" (the most accurate settings) and the
difference set beside the noise: the root mean square of the same comparison between every
pair of the reference's seeds ("reference", "reference-seed-2", ...; at least 4 seeds, 6
pairs), or, in a study from before those cases, between the case "scene" (the scene as
given) and "seed-2" (one pair). A difference at or below the noise is not an error the
setting made; for delta/D the noise is at least the combined block errors of two runs,
since the seeds can agree by chance. Writes OUT_DIR/trade.csv and trade.json (every number),
trade.md (the table of docs/accuracy.md) and pareto.png (speed-up against each error).
The e_eff error is given for one impact (one phase of the first contact step on the time
grid) and averaged over the phases (the one `granshock run --accuracy` judges).
"""
import csv
import json
import os
import sys

import tomllib

import h5py
import numpy as np

DEFINITIONS = ["temperature_jump", "sonic_line", "density_threshold"]
FIELDS = ["phi", "T", "Ma"]


def load(study, name):
    d = os.path.join(study, name)
    s = json.load(open(os.path.join(d, "summary.json")))
    with h5py.File(os.path.join(d, "fields.h5"), "r") as f:
        fields = {q: f["fields/" + q][...] for q in FIELDS}
        # Bins that hold on average less than half a particle (the nearly empty wake) are
        # left out: a few samples of a cold particle give Ma up to 5e7 there.
        fields["masked"] = (f["fields/masked"][...] != 0) | (f["fields/mean_count"][...] < 0.5)
    return s, fields


# Keys that differ between cases without being the setting a case names: the case's name,
# the sample interval in steps (kept constant in time), and sigma where the run calibrates
# it to the Mach number (inflow.mach_at = "inlet_bins").
INCIDENTAL = {"scene.name", "output.sample_every", "inflow.sigma"}


def resolved_scene(study, name):
    with h5py.File(os.path.join(study, name, "run.h5"), "r") as f:
        text = f["scene/resolved"][()]
    return tomllib.loads(text.decode() if isinstance(text, bytes) else text)


def flatten(table, prefix=""):
    out = {}
    for k, v in table.items():
        if isinstance(v, dict):
            out.update(flatten(v, prefix + k + "."))
        else:
            out[prefix + k] = v
    return out


def changed_keys(case_scene, scene):
    """The scene keys a case changes against the scene as given (the case "scene")."""
    a, b = flatten(case_scene), flatten(scene)
    return sorted(k for k in set(a) | set(b) if k not in INCIDENTAL and a.get(k) != b.get(k))


def e_eff_error(summary, key="e_eff"):
    """Largest |e_eff / e - 1| over the pairs at the inflow speed, at the run's dt: key
    "e_eff" is one impact (one phase of the first contact step on the time grid),
    "e_eff_phase_averaged" the average over the phases, what a gas of impacts sees and what
    the discrete restitution mode is calibrated on (docs/accuracy.md). None where the run's
    summary.json is from before it was recorded."""
    worst = 0.0
    for pair in summary["effective_restitution_at_dt"].values():
        e, at = pair["e_in"], pair["at_inflow_speed"]
        if key not in at:
            return None
        worst = max(worst, abs(at[key] / e - 1))
    return worst


def scalars(summary):
    out = {}
    for k in DEFINITIONS:
        out["delta_over_D." + k] = summary["detachment"][k]["delta_over_D"]
    for k in ["phi_peak", "ma_inf_measured", "shock_angle_deg"]:
        out[k] = summary.get(k)
    return out


def l2(a, b):
    """Relative L2 difference of field a against b over the bins used in both."""
    ok = ~a["masked"] & ~b["masked"]
    out = {}
    for q in FIELDS:
        x, y = a[q][ok], b[q][ok]
        good = np.isfinite(x) & np.isfinite(y)
        out["L2." + q] = float(np.sqrt(np.sum((x[good] - y[good]) ** 2) / np.sum(y[good] ** 2)))
    return out


def differences(case, ref):
    (sc, fc), (sr, fr) = case, ref
    a, b = scalars(sc), scalars(sr)
    out = {k: (abs(a[k] - b[k]) if a[k] is not None and b[k] is not None else None) for k in a}
    out.update(l2(fc, fr))
    return out


MIN_REFERENCE_SEEDS = 4


def seed_noise(runs, seeds):
    """The noise of a difference between two runs of one seed each: for every quantity the
    root mean square of its difference over every pair of `seeds` (for a scalar about
    sqrt(2) times its standard deviation over the seeds; for an L2 difference of fields,
    that of two runs that differ by the seed alone). For delta/D at least the combined
    block errors of two runs (sqrt(2) times their RMS), since the seeds can agree by chance
    (docs/fields.md, section 6)."""
    pairs = [(a, b) for i, a in enumerate(seeds) for b in seeds[i + 1:]]
    per_pair = [differences(runs[a], runs[b]) for a, b in pairs]
    noise = {}
    for k in per_pair[0]:
        values = [d[k] for d in per_pair if d[k] is not None]
        noise[k] = float(np.sqrt(np.mean(np.square(values)))) if values else None
    for k in DEFINITIONS:
        errs = [runs[n][0]["detachment"][k].get("delta_over_D_err") for n in seeds]
        if noise["delta_over_D." + k] is not None and None not in errs:
            noise["delta_over_D." + k] = max(noise["delta_over_D." + k],
                                             float(np.sqrt(2 * np.mean(np.square(errs)))))
    return noise


def main(study, out_dir, figures=True):
    names = [r["case"] for r in csv.DictReader(open(os.path.join(study, "study.csv")))]
    runs = {n: load(study, n) for n in names}
    ref = runs["reference"]
    seeds = ["reference"] + sorted(n for n in names if n.startswith("reference-seed-"))
    if len(seeds) >= MIN_REFERENCE_SEEDS:
        noise = seed_noise(runs, seeds)
        noise_from = f"the reference's {len(seeds)} seeds, RMS over their {len(seeds) * (len(seeds) - 1) // 2} pairs"
    else:
        noise = seed_noise(runs, ["scene", "seed-2"])
        noise_from = "scene against seed-2"
    title = os.path.basename(os.path.normpath(study))
    # The cost of a case: its CPU time where every case recorded one (summary.json
    # cpu_seconds: on a shared machine wall time also counts the other programs' turns,
    # and a run that found the machine busy ran on fewer threads), else its wall time.
    cost_key = ("cpu_seconds" if all(runs[n][0].get("cpu_seconds") for n in names)
                else "wall_seconds")
    cost_ref = ref[0][cost_key]
    scenes = {n: resolved_scene(study, n) for n in names}
    rows = []
    for n in names:
        s = runs[n][0]
        contact = scenes[n]["contact"]
        # The settings `granshock run --accuracy` chooses from (docs/accuracy.md).
        row = {"case": n, "changed": " ".join(changed_keys(scenes[n], scenes["scene"])),
               "softening": contact.get("softening", 1.0),
               "precision": scenes[n]["numerics"]["precision"],
               "restitution_mode": contact["restitution_mode"],
               "dt": s["dt"], "dt_over_tc": s["dt_over_tc"],
               "wall_seconds": s["wall_seconds"],
               "cpu_seconds": s.get("cpu_seconds"),
               "cost_from": cost_key,
               "speedup": cost_ref / s[cost_key],
               "particle_steps_per_second": s["particle_steps_per_second"],
               "e_eff_error": e_eff_error(s),
               "e_eff_error_phase_averaged": e_eff_error(s, "e_eff_phase_averaged")}
        if row["e_eff_error_phase_averaged"] is None:
            sys.exit(f"{n}/summary.json has no e_eff_phase_averaged (a run from before it was "
                     "recorded): make the table from a study of this granshock, or add the "
                     "column to an existing table with cases/tradeoff/phase_averaged_e_eff.py")
        row.update({k: v for k, v in scalars(s).items()})
        diff = differences(runs[n], ref)
        for k, v in diff.items():
            row["diff." + k] = v
            row["over_noise." + k] = v / noise[k] if v is not None and noise[k] else None
        rows.append(row)
    write_tables(rows, noise, out_dir, noise_from)
    if figures:
        write_figure(rows, noise, title, out_dir)


def write_tables(rows, noise, out_dir, noise_from, extra=None):
    """trade.csv, trade.json and trade.md of the rows (also cases/tradeoff/phase_averaged_e_eff.py,
    which passes the keys of the table it rewrites that are not the rows' in `extra`)."""
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "trade.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out_dir, "trade.json"), "w") as f:
        json.dump({"table": "granshock trade table 1", "noise": noise, "noise_from": noise_from,
                   **(extra or {}), "cases": rows}, f, indent=1)

    def cell(r, k, fmt):
        v, q = r["diff." + k], r["over_noise." + k]
        if v is None:
            return "n/a"
        mark = " (noise)" if q is not None and q <= 1 else ""
        return f"{v:{fmt}}{mark}"

    def num(v, spec):
        return "n/a" if v is None else f"{v:{spec}}"

    cost_key = rows[0]["cost_from"]
    cost_label = "CPU (s)" if cost_key == "cpu_seconds" else "wall (s)"
    lines = [f"| case | dt/t_c | {cost_label} | speed-up | e_eff error, phase-averaged | "
             "e_eff error, one phase | delta/D (primary) | "
             "|delta/D - ref| | L2 phi | L2 T | L2 Ma | |phi_peak - ref| | |Ma_inf - ref| |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['case']} | {r['dt_over_tc']:.3f} | {r[cost_key]:.1f} | "
            f"{r['speedup']:.2f} | {100 * r['e_eff_error_phase_averaged']:.2f} % | "
            f"{100 * r['e_eff_error']:.2f} % | "
            f"{num(r['delta_over_D.temperature_jump'], '.3f')} | "
            f"{cell(r, 'delta_over_D.temperature_jump', '.3f')} | {cell(r, 'L2.phi', '.3f')} | "
            f"{cell(r, 'L2.T', '.3f')} | {cell(r, 'L2.Ma', '.3f')} | "
            f"{cell(r, 'phi_peak', '.3f')} | {cell(r, 'ma_inf_measured', '.3f')} |")
    lines.append("")
    lines.append(f"Noise ({noise_from}): " + ", ".join(
        f"{k} {v:.3g}" for k, v in noise.items() if v is not None))
    open(os.path.join(out_dir, "trade.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


def write_figure(rows, noise, title, out_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, key, label in [(axes[0], "L2.phi", "relative L2 difference of phi"),
                           (axes[1], "delta_over_D.temperature_jump", "|delta/D - reference|")]:
        for r in rows:
            if r["case"] == "reference":
                continue
            v = r["diff." + key]
            if v is None:
                continue
            ax.scatter(r["speedup"], max(v, 1e-5), color="C0")
            ax.annotate(r["case"], (r["speedup"], max(v, 1e-5)), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
        if noise[key]:
            ax.axhline(noise[key], color="C3", ls="--", label="noise (seeds)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("speed-up against the reference (" + (
            "CPU time" if rows[0]["cost_from"] == "cpu_seconds" else "wall time") + ")")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        if noise[key]:
            ax.legend(fontsize=8)
    fig.suptitle(f"{title}: speed against accuracy")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "pareto.png"), dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4) or sys.argv[3:] not in ([], ["--no-figures"]):
        sys.exit("usage: trade_table.py STUDY_DIR OUT_DIR [--no-figures]")
    main(sys.argv[1], sys.argv[2], figures=sys.argv[3:] != ["--no-figures"])

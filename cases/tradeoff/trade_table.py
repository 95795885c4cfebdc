#!/usr/bin/python3
"""The speed-against-accuracy table of `granshock tradeoff` (docs/accuracy.md).

Usage: /usr/bin/python3 trade_table.py RECORDS_DIR OUT_DIR [--no-figures] (granshock
tradeoff runs it; --no-figures: the tables without pareto.png)

RECORDS_DIR holds the study's case records (docs/study.md, "Campaign records"): one folder
cases/<case>/ each, with summary.json, scene.toml and the reduced fields.h5, and the study's
study.csv, whose order the table keeps. The run directories are not read: the table can be
made again from committed records.

Every case is compared with the case "reference" (the most accurate settings) and the
difference set beside the noise: the root mean square of the same comparison between every
pair of the seeds of the scene as given ("scene", "seed-2", "seed-3", ...; at least 4 seeds,
6 pairs); in a table from before those cases, the reference's seeds ("reference",
"reference-seed-2", ...) or "scene" against "seed-2" (one pair). For delta/D the noise is
at least the combined block errors of two runs, since the seeds can agree by chance. The
certificate of a case (docs/accuracy.md, "The certificate") bounds each answer's error by
|difference| + k x noise, k the one-sided Student t quantile at CONFIDENCE with seeds - 1
degrees of freedom. Writes OUT_DIR/trade.csv and trade.json (every number), trade.md (the
table of docs/accuracy.md) and pareto.png (speed-up against each error). The e_eff error is
given for one impact (one phase of the first contact step on the time grid) and averaged
over the phases (the one `granshock run --accuracy` judges).
"""
import csv
import json
import os
import re
import sys

import tomllib

import h5py
import numpy as np

# The layout of trade.json (cases/accuracy/accuracy_table.hpp, kTradeTableVersion).
TABLE_VERSION = "granshock trade table 2"
DEFINITIONS = ["temperature_jump", "sonic_line", "density_threshold"]
FIELDS = ["phi", "T", "Ma"]


def case_dir(records, name):
    return os.path.join(records, "cases", name)


def case_names(records):
    """The recorded cases, in study.csv's order where the records have one."""
    recorded = {n for n in os.listdir(os.path.join(records, "cases"))
                if os.path.isfile(os.path.join(case_dir(records, n), "summary.json"))}
    table = os.path.join(records, "study.csv")
    if not os.path.isfile(table):
        return sorted(recorded)
    order = [r["case"] for r in csv.DictReader(open(table))]
    return [n for n in order if n in recorded] + sorted(recorded - set(order))


def load(records, name):
    d = case_dir(records, name)
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


def resolved_scene(records, name):
    with open(os.path.join(case_dir(records, name), "scene.toml"), "rb") as f:
        return tomllib.load(f)


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


MIN_NOISE_SEEDS = 4
# The confidence of a certificate's bound (one-sided) and the Student t quantiles it takes,
# by degrees of freedom (seeds - 1): scipy is not among the project's packages.
CONFIDENCE = 0.90
T_QUANTILE_90 = {1: 3.078, 2: 1.886, 3: 1.638, 4: 1.533, 5: 1.476, 6: 1.440, 7: 1.415,
                 8: 1.397, 9: 1.383, 10: 1.372}


def t_quantile(seeds):
    return T_QUANTILE_90.get(seeds - 1, 1.2816)  # past 11 seeds, the normal quantile


def noise_seeds(names):
    """The runs whose spread is the noise, and what the table says of them."""
    scene = ["scene"] + sorted((n for n in names if re.fullmatch(r"seed-\d+", n)),
                               key=lambda n: int(n.split("-")[1]))
    reference = ["reference"] + sorted(n for n in names if n.startswith("reference-seed-"))
    for seeds, what in [(scene, "the scene's"), (reference, "the reference's")]:
        if len(seeds) >= MIN_NOISE_SEEDS:
            pairs = len(seeds) * (len(seeds) - 1) // 2
            return seeds, f"{what} {len(seeds)} seeds, RMS over their {pairs} pairs"
    return ["scene", "seed-2"], "scene against seed-2"


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


def build_table(records):
    """The table of one records folder: (rows, noise, noise_from, title, extra), extra the
    keys of trade.json beside its cases (the seeds, the certificate, the noise floor, the
    reference's second seed, its own range)."""
    names = case_names(records)
    missing = [n for n in ["reference", "scene", "seed-2"] if n not in names]
    if missing:
        sys.exit(f"{records}: no record of the case{'s' if len(missing) > 1 else ''} "
                 f"{', '.join(missing)}: the table needs the reference and two seeds of the scene")
    runs = {n: load(records, n) for n in names}
    ref = runs["reference"]
    seeds, noise_from = noise_seeds(names)
    noise = seed_noise(runs, seeds)
    k = t_quantile(len(seeds))
    certificate = {"confidence": CONFIDENCE, "sided": "one", "k": k, "seeds": len(seeds),
                   "pairing": "unpaired",
                   "rule": "|difference| + k x noise, relative to the reference's value"}
    # A study's own records are <out>/records: named after the study's directory.
    title = os.path.basename(os.path.normpath(records))
    if title == "records":
        title = os.path.basename(os.path.dirname(os.path.normpath(records)))
    # The cost of a case: its CPU time where every case recorded one (summary.json
    # cpu_seconds: on a shared machine wall time also counts the other programs' turns,
    # and a run that found the machine busy ran on fewer threads), else its wall time.
    cost_key = ("cpu_seconds" if all(runs[n][0].get("cpu_seconds") for n in names)
                else "wall_seconds")
    cost_ref = ref[0][cost_key]
    scenes = {n: resolved_scene(records, n) for n in names}
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
               # A cost measured on another CPU than the reference's compares machines, not
               # settings: the table says so beside its speed-up.
               "cpu_model": s.get("cpu_model"),
               "cost_on_reference_cpu": s.get("cpu_model") == ref[0].get("cpu_model"),
               "particle_steps_per_second": s["particle_steps_per_second"],
               "e_eff_error": e_eff_error(s),
               "e_eff_error_phase_averaged": e_eff_error(s, "e_eff_phase_averaged")}
        if row["e_eff_error_phase_averaged"] is None:
            sys.exit(f"{n}/summary.json has no e_eff_phase_averaged (a run from before it was "
                     "recorded): make the table from a study of this granshock, or add the "
                     "column to an existing table with cases/tradeoff/phase_averaged_e_eff.py")
        row.update({k: v for k, v in scalars(s).items()})
        diff = differences(runs[n], ref)
        for q, v in diff.items():
            row["diff." + q] = v
            row["over_noise." + q] = v / noise[q] if v is not None and noise[q] else None
        rows.append(row)
    reference_row = rows[names.index("reference")]
    for row in rows:
        row["bound"], row["bound_by"] = certificate_bound(row, reference_row, noise, k)
    floor = noise_floor(reference_row, noise, k)
    extra = {"noise_seeds": len(seeds), "certificate": certificate, "noise_floor": floor,
             "bias_second_seed": second_seed_bias(runs)}
    shown = own_range(records, title)
    if shown:
        extra["certified_range"] = shown
    return rows, noise, noise_from, title, extra


def main(records, out_dir, figures=True):
    rows, noise, noise_from, title, extra = build_table(records)
    write_tables(rows, noise, out_dir, noise_from, extra)
    if figures:
        write_figure(rows, noise, title, out_dir)


def own_range(records, title):
    """Where the table holds before any transfer check: its reference's D/d and Ma_inf, from
    the study table beside the records (its columns scene.D_over_d, the obstacle's frontal
    width over units.d, and scene.mach); None without them. `granshock tradeoff` writes
    its scene's point itself (cases/accuracy/accuracy_range.hpp), by the mean diameter."""
    table = os.path.join(records, "study.csv")
    if not os.path.isfile(table):
        return None
    for r in csv.DictReader(open(table)):
        if r["case"] == "reference" and r.get("scene.D_over_d") and r.get("scene.mach"):
            D, ma = float(r["scene.D_over_d"]), float(r["scene.mach"])
            return {"D_over_d": [D, D], "mach": [ma, ma], "shown_on": [title]}
    return None


BUDGET_ANSWERS = ["delta_over_D." + d for d in DEFINITIONS] + ["phi_peak", "ma_inf_measured"]


def certificate_bound(row, reference_row, noise, k):
    """The bound `granshock run --accuracy` gives the case (docs/accuracy.md, "The
    certificate"; computed again there, cases/accuracy/accuracy_table.cpp): the largest of
    its phase-averaged e_eff error and (|difference| + k x noise) / |reference| over the
    answers the reference has; None (unbounded) where the case lost one of them."""
    bound, by = row["e_eff_error_phase_averaged"], "e_eff (phase-averaged)"
    for q in BUDGET_ANSWERS:
        ref, n = reference_row.get(q), noise.get(q)
        if not ref or n is None:
            continue
        d = row.get("diff." + q)
        if d is None:
            return None, q
        if (d + k * n) / abs(ref) > bound:
            bound, by = (d + k * n) / abs(ref), q
    return bound, by


def noise_floor(reference_row, noise, k):
    """The smallest bound a certificate can give: k x noise / |reference| of the answer
    where it is largest (a setting identical to the reference is bounded by it)."""
    worst = {"bound": 0.0, "by": None}
    for q in BUDGET_ANSWERS:
        ref, n = reference_row.get(q), noise.get(q)
        if ref and n is not None and k * n / abs(ref) > worst["bound"]:
            worst = {"bound": k * n / abs(ref), "by": q}
    return worst


def second_seed_bias(runs):
    """The scene's setting against the reference on the second seed's particles, beside the
    first seed's: the same bias measured twice (None without reference-seed-2)."""
    if "reference-seed-2" not in runs or "seed-2" not in runs:
        return None
    return {"seed-2 against reference-seed-2": differences(runs["seed-2"], runs["reference-seed-2"]),
            "scene against reference": differences(runs["scene"], runs["reference"])}


def write_tables(rows, noise, out_dir, noise_from, extra=None, version=TABLE_VERSION):
    """trade.csv, trade.json and trade.md of the rows (also cases/tradeoff/phase_averaged_e_eff.py,
    which passes the keys of the table it rewrites that are not the rows' in `extra`, and
    that table's version)."""
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "trade.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out_dir, "trade.json"), "w") as f:
        json.dump({"table": version, "noise": noise, "noise_from": noise_from,
                   **(extra or {}), "cases": rows}, f, indent=1)

    def cell(r, k, fmt):
        v, q = r["diff." + k], r["over_noise." + k]
        if v is None:
            return "n/a"
        mark = " (noise)" if q is not None and q <= 1 else ""
        return f"{v:{fmt}}{mark}"

    def num(v, spec):
        return "n/a" if v is None else f"{v:{spec}}"

    def other_cpu(r):
        if r.get("cost_on_reference_cpu", True):
            return ""
        return f" (on another CPU: {r.get('cpu_model') or 'unknown'})"

    cost_key = rows[0]["cost_from"]
    cost_label = "CPU (s)" if cost_key == "cpu_seconds" else "wall (s)"
    bounds = "bound" in rows[0]
    lines = [f"| case | dt/t_c | {cost_label} | speed-up | e_eff error, phase-averaged | "
             "e_eff error, one phase | delta/D (primary) | "
             "|delta/D - ref| | L2 phi | L2 T | L2 Ma | |phi_peak - ref| | |Ma_inf - ref| |"
             + (" certified bound (set by) |" if bounds else ""),
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|" + ("---|" if bounds else "")]
    for r in rows:
        lines.append(
            f"| {r['case']} | {r['dt_over_tc']:.3f} | {r[cost_key]:.1f} | "
            f"{r['speedup']:.2f}{other_cpu(r)} | {100 * r['e_eff_error_phase_averaged']:.2f} % | "
            f"{100 * r['e_eff_error']:.2f} % | "
            f"{num(r['delta_over_D.temperature_jump'], '.3f')} | "
            f"{cell(r, 'delta_over_D.temperature_jump', '.3f')} | {cell(r, 'L2.phi', '.3f')} | "
            f"{cell(r, 'L2.T', '.3f')} | {cell(r, 'L2.Ma', '.3f')} | "
            f"{cell(r, 'phi_peak', '.3f')} | {cell(r, 'ma_inf_measured', '.3f')} |"
            + (f" {num(r['bound'] and 100 * r['bound'], '.2f')} % ({r['bound_by']}) |"
               if bounds else ""))
    lines.append("")
    lines.append(f"Noise ({noise_from}): " + ", ".join(
        f"{k} {v:.3g}" for k, v in noise.items() if v is not None))
    if extra and "certificate" in extra:
        c, floor = extra["certificate"], extra["noise_floor"]
        lines.append("")
        lines.append(f"Certificate: {c['rule']}, k = {c['k']:.3f} (one-sided "
                     f"{100 * c['confidence']:.0f} %, Student t with {c['seeds'] - 1} degrees of "
                     f"freedom, {c['pairing']}); noise floor {100 * floor['bound']:.2f} % "
                     f"(set by {floor['by']}).")
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
        sys.exit("usage: trade_table.py RECORDS_DIR OUT_DIR [--no-figures]")
    main(sys.argv[1], sys.argv[2], figures=sys.argv[3:] != ["--no-figures"])

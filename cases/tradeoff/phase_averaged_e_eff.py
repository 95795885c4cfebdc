#!/usr/bin/python3
"""Adds the phase-averaged e_eff error to a trade table made before it was recorded
(docs/accuracy.md, "Choosing settings for an error budget").

Usage: /usr/bin/python3 phase_averaged_e_eff.py GRANSHOCK STUDY.toml TRADE_DIR

e_eff at a run's dt depends only on the case's contact settings (dt, softening,
restitution mode, the pairs and the inflow speed), not on how long the case ran: each case
of the study is run again for 200 of its own steps (fields sampled every step from t = 0,
the inflow's sigma as given instead of calibrated, which changes neither), and its
summary.json gives e_eff of every pair at the inflow speed, of one impact and averaged over
the phase of the first contact step. The one-impact error must equal the table's
e_eff_error (the same settings); the phase-averaged one is added as
e_eff_error_phase_averaged, and TRADE_DIR's trade.csv, trade.json and trade.md are written
again (every other number as it was; pareto.png does not show e_eff).
"""
import json
import os
import subprocess
import sys
import tempfile

import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import trade_table  # noqa: E402

STEPS = 200  # at one sample per step: the 10 field blocks need 100 samples


def short_run(granshock, base, sets, dt, out):
    cmd = [granshock, "run", base, "--out", out, "--quiet"]
    for s in sets + [f"time.duration={STEPS * dt!r}", "time.production_start=0.0",
                     "output.sample_every=1", 'inflow.mach_at="inserted"']:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    return json.load(open(os.path.join(out, "summary.json")))


def main(granshock, study_file, trade_dir):
    study = tomllib.load(open(study_file, "rb"))
    base = os.path.normpath(os.path.join(os.path.dirname(study_file), study["study"]["base"]))
    common = study["study"].get("set", [])
    sets = {c["name"]: common + c.get("set", []) for c in study["case"]}
    doc = json.load(open(os.path.join(trade_dir, "trade.json")))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for row in doc["cases"]:
            name = row["case"]
            if name not in sets:
                sys.exit(f"{study_file} has no case {name!r} of {trade_dir}/trade.json")
            s = short_run(granshock, base, sets[name], row["dt"], os.path.join(tmp, name))
            one = trade_table.e_eff_error(s)
            if abs(one - row["e_eff_error"]) > 1e-9 * max(1.0, row["e_eff_error"]):
                sys.exit(f"case {name!r}: e_eff error {one!r} at one phase, the table has "
                         f"{row['e_eff_error']!r}: not the settings the table measured")
            out = {}
            for k, v in row.items():
                if k != "e_eff_error_phase_averaged":
                    out[k] = v
                if k == "e_eff_error":
                    out["e_eff_error_phase_averaged"] = trade_table.e_eff_error(
                        s, "e_eff_phase_averaged")
            rows.append(out)
            print(f"{name}: e_eff error {100 * one:.2f} % at one phase, "
                  f"{100 * out['e_eff_error_phase_averaged']:.2f} % phase-averaged",
                  file=sys.stderr)
    kept = {k: v for k, v in doc.items() if k not in ("table", "noise", "noise_from", "cases")}
    trade_table.write_tables(rows, doc["noise"], trade_dir,
                             doc.get("noise_from", "scene against seed-2"), kept,
                             doc.get("table", trade_table.TABLE_VERSION))


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit("usage: phase_averaged_e_eff.py GRANSHOCK STUDY.toml TRADE_DIR")
    main(*sys.argv[1:])

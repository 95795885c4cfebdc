#!/usr/bin/python3
"""The seed-spread tables of README.md from the runs' summary.json files.

Usage: /usr/bin/python3 spread.py seed1 seed2 ... (run directories of one scene that
differ only in scene.seed). Prints the two markdown tables: per definition, delta/D of
each seed, their mean and standard deviation, the rms of the reported errors and the
ratio std / error (1: the error bars are right); per seed, the primary definition's
verdict.
"""
import json
import math
import sys

DEFINITIONS = ["temperature_jump", "density_threshold", "density_max_gradient", "sonic_line"]


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def main(runs):
    summaries = [json.load(open(f"{run}/summary.json")) for run in runs]
    print("| definition | delta/D, seeds | mean | std over seeds | rms reported error "
          "| std / error | rms error: blocks / merged pairs / bootstrap |")
    print("|---|---|---|---|---|---|---|")
    for name in DEFINITIONS:
        d = [s["detachment"][name] for s in summaries]
        values = [x["delta_over_D"] for x in d]
        if any(v is None for v in values):
            print(f"| {name} | some seed has no front | | | | | |")
            continue
        mean = sum(values) / len(values)
        std = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))
        err = rms([x["delta_over_D_err"] for x in d])
        parts = " / ".join(f"{rms([x['delta_over_D_err_' + k] for x in d]):.4f}"
                           for k in ("blocks", "merged_pairs", "bootstrap"))
        print(f"| {name} | {', '.join(f'{v:.3f}' for v in values)} | {mean:.3f} | "
              f"{std:.4f} | {err:.4f} | {std / err:.2f} | {parts} |")
    print()
    print("| seed | Ma_inf at the inlet | delta/D (primary) +- error "
          "| primary consistent across cuts | verdict |")
    print("|---|---|---|---|---|")
    for run, s in zip(runs, summaries):
        print(f"| {run.removeprefix('seed')} | {s['ma_inf_measured']:.2f} | "
              f"{s['delta_over_D']:.3f} +- {s['delta_over_D_err']:.3f} | "
              f"{s['delta_over_D_consistent']} | {s['delta_over_D_verdict']} |")


if __name__ == "__main__":
    main(sys.argv[1:])

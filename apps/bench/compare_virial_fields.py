#!/usr/bin/env python3
"""The collisional stress of two runs of the same scene, bin by bin, against its block errors.

Usage: compare_virial_fields.py OLD_RUN_DIR NEW_RUN_DIR

For runs whose trajectories are the same but whose sampled contact virial differs (docs/fields.md,
"The contact virial"): per bin of the grid and of the stagnation-line profile (run.h5,
/fields/{grid,profile}/sums [blocks, ny, nx, q]; docs/output_format.md) it takes the contact
virial per sample, W_xx, W_xy, W_yy and the collisional pressure (W_xx + W_yy) / 2, which
P_col and the pressure field are these divided by the bin area (docs/fields.md, section 2). The
block error is the standard error of the block means (as the analysis's block errors,
docs/fields.md, "Error bars"), of the old run. Prints, per quantity, over the bins with contacts
in every block (a bin with contacts in one block alone has an error as large as its mean, and
says nothing), the median and the largest |new - old| / error, the bins beyond one error and
the change of the sum over all bins (new / old - 1).
"""
import sys

import h5py
import numpy as np

VIRIAL = {"W_xx": (0,), "W_xy": (1,), "W_yy": (3,), "collisional pressure": (0, 3)}


def per_sample_blocks(run_dir, layout):
    with h5py.File(f"{run_dir}/run.h5", "r") as f:
        group = f[f"/fields/{layout}"]
        blocks, ny, nx = (int(group.attrs[k]) for k in ("blocks", "ny", "nx"))
        sums = np.asarray(group["sums"]).reshape(blocks, ny, nx, -1)
        samples = np.asarray(group["samples"], dtype=float)
    return sums[..., -4:], samples  # the virial: W_xx, W_xy, W_yx, W_yy


def compare(old_dir, new_dir, layout):
    old, samples = per_sample_blocks(old_dir, layout)
    new, new_samples = per_sample_blocks(new_dir, layout)
    if old.shape != new.shape or not np.array_equal(samples, new_samples):
        sys.exit(f"{layout}: the two runs' bins or samples differ")
    used = samples > 0
    for name, terms in VIRIAL.items():
        a = sum(old[..., t] for t in terms) / len(terms)
        b = sum(new[..., t] for t in terms) / len(terms)
        block_means = a[used] / samples[used][:, None, None]
        error = block_means.std(axis=0, ddof=1) / np.sqrt(used.sum())
        mean_old = a[used].sum(axis=0) / samples.sum()
        mean_new = b[used].sum(axis=0) / samples.sum()
        ok = np.all(block_means != 0, axis=0) & (error > 0)
        ratio = np.abs(mean_new - mean_old)[ok] / error[ok]
        change = mean_new.sum() / mean_old.sum() - 1 if mean_old.sum() != 0 else float("nan")
        print(f"{layout:8s} {name:21s} bins {ok.sum():6d}  |new-old|/error median "
              f"{np.median(ratio):.3f}  largest {ratio.max():.3f}  beyond 1: {(ratio > 1).sum():3d}"
              f"  sum over bins new/old - 1 = {change:+.4f}")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    for layout in ("grid", "profile"):
        compare(sys.argv[1], sys.argv[2], layout)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Checks that the figures of plot_fields.py show masked bins blank (docs/fields.md,
section 8): the values it draws are NaN in every masked bin, phi included (phi stays
defined in fields.h5 where a bin was sampled), and in every masked profile bin.

Usage: check_figure_masking.py FIELDS_H5 SCRIPT_DIR
"""
import sys

import h5py
import numpy as np


def main():
    fields_h5, script_dir = sys.argv[1], sys.argv[2]
    sys.path.insert(0, script_dir)
    import plot_fields  # noqa: E402

    run = plot_fields.Run(fields_h5)
    failures = []
    masked = run.fields["masked"] != 0
    for name in ("phi", "T_norm", "Ma"):
        if not np.all(np.isnan(run.fields[name][masked])):
            failures.append(f"{name}: a masked bin would be drawn")
    with h5py.File(fields_h5, "r") as f:
        phi = f["fields/phi"][...]
        profile_masked = f["profile/masked"][...] != 0
    shown = ~masked & np.isfinite(phi)
    if not np.array_equal(run.fields["phi"][shown], phi[shown]):
        failures.append("phi: an unmasked bin is not drawn as it is")
    if not np.all(np.isnan(run.profile["phi"][profile_masked])):
        failures.append("profile phi: a masked bin would be drawn")
    for message in failures:
        print(f"{fields_h5}: {message}", file=sys.stderr)
    print(f"{fields_h5}: {int(masked.sum())} of {masked.size} bins masked, "
          f"{int(profile_masked.sum())} of {profile_masked.size} profile bins masked: "
          f"{'FAILED' if failures else 'blank in the figures'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

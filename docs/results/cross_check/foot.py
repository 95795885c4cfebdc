#!/usr/bin/python3
"""How far upstream the temperature rise of a bow shock reaches: the farthest point of
the stagnation-line profile, within 20 d of the cylinder's face, where T exceeds three
times its mean at 20-40 d from the face (README.md here, "granshock's sensitivity").

Usage: foot.py LABEL=DIR [LABEL=DIR ...]   (DIR: a granshock run or --from-dump output
with fields.h5, docs/output_format.md)
"""
import sys

import h5py
import numpy as np

FACTOR = 3.0


def foot(directory):
    with h5py.File(f"{directory}/fields.h5", "r") as h:
        y = h["profile/y"][()]
        t = h["profile/T_norm"][()]
        face, d = h.attrs["obstacle_face"], h.attrs["d"]
    dist = (face - y) / d
    upstream = np.nanmean(t[(dist > 20) & (dist < 40)])
    near = (dist > 0) & (dist < 20) & (t > FACTOR * upstream)
    return upstream, (dist[near].max() if near.any() else float("nan"))


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    print(f"| analysis | T/(m U^2) at 20-40 d | foot (T > {FACTOR:g} times that) |")
    print("|---|---|---|")
    for arg in argv[1:]:
        label, directory = arg.split("=", 1)
        upstream, reach = foot(directory)
        print(f"| {label} | {upstream:.5f} | {reach:.1f} d |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/python3
"""Digest of a granshock run directory for the bitwise reference check.

Prints one JSON object: the SHA-256 of every dataset of checkpoint.h5 /state (the final
particle state, neighbour list included), a fingerprint of the field sums in run.h5, and
every summary.json value that does not depend on the machine or the clock. Two runs of
the same scene by two builds have equal state digests exactly when their trajectories are
bitwise equal; field sums and the numbers derived from them agree to round-off.

Usage: digest.py RUN_DIR
"""
import hashlib
import json
import sys

import h5py
import numpy

# summary.json keys that measure the machine, or name the program, not the physics: the
# launches per step depend on the build's paths and on how the wall clock slices the loop
# (docs/cuda.md, "Launches per step").
MACHINE_KEYS = {"wall_seconds", "cpu_seconds", "particle_steps_per_second", "threads",
                "backend", "cpu_model", "variant", "backend_switch", "build", "kernel_launches_per_step",
                "reductions_per_step", "deep_copies_per_step", "device_to_host_copies_per_step",
                "fences_per_step", "host_reads_per_step", "thread_shares"}


def sha(array):
    return hashlib.sha256(numpy.ascontiguousarray(array).tobytes()).hexdigest()[:32]


def fingerprint(sums):
    """Field sums are accumulated with atomic adds, whose order varies between runs: they
    are reproducible to round-off, not bitwise. Their fingerprint is, per block and
    quantity, the total over bins and the total weighted by the flat bin index (which
    moves when a sample lands in another bin), compared to a relative 1e-9."""
    blocks, quantities = sums.shape[0], sums.shape[-1]
    flat = sums.reshape(blocks, -1, quantities)
    weights = numpy.arange(1, flat.shape[1] + 1, dtype=float)[None, :, None]
    return {"totals": flat.sum(axis=1).round(12).tolist(),
            "weighted": (flat * weights).sum(axis=1).tolist()}


def main(run_dir):
    digest = {"state": {}, "fields": {}, "summary": {}}
    with h5py.File(f"{run_dir}/checkpoint.h5", "r") as f:
        for name, item in sorted(f["state"].items()):
            digest["state"][name] = sha(item[()])
        for name in ("step", "next_id", "list_builds"):
            digest["state"]["@" + name] = int(f["state"].attrs[name])
    with h5py.File(f"{run_dir}/run.h5", "r") as f:
        for path in ("fields/grid/sums", "fields/profile/sums"):
            if path in f:
                digest["fields"][path] = fingerprint(f[path][()])
    with open(f"{run_dir}/summary.json") as f:
        summary = json.load(f)
    # A warning about the run's data names its directory, which is the machine's: RUN.
    if isinstance(summary.get("warnings"), list):
        summary["warnings"] = [w.replace(str(run_dir), "RUN") for w in summary["warnings"]]
    digest["summary"] = {k: v for k, v in sorted(summary.items()) if k not in MACHINE_KEYS}
    json.dump(digest, sys.stdout, indent=1, sort_keys=True)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main(sys.argv[1])

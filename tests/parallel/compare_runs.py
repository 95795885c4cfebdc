"""Two run directories of the same scene, one from one process and one from several
(docs/parallel.md), or from one process that was stopped and resumed: the checkpoint's
particle state and run.h5's particle snapshots must be the same bit for bit; the field
sums and energy series, whose sums run in another order, the same to within 1e-11 of each
array's largest magnitude. A run on several processes must also be long enough to mean
something: it must have crossed MIN_LIST_BUILDS neighbour-list rebuilds and handed
MIN_MIGRATED particles between slabs (summary.json, "processes"). Prints what differs;
exit status 1 if anything does.
Usage: compare_runs.py ONE_PROCESS_DIR OTHER_DIR RANKS
"""
import json
import sys

import h5py
import numpy as np

ROUNDING = 1e-11
# A shortened run still exercises what several processes do between and at rebuilds. In
# tests/cli/mpi_run.sh's 4 ms (41 rebuilds) slabs along y hand over 71 to 281 particles in
# all, slabs along x, crossed by the thermal motion alone, 7 to 20 (docs/parallel.md).
MIN_LIST_BUILDS = 20
MIN_MIGRATED = 5


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()])
                     if isinstance(obj, h5py.Dataset) else None)
    return out


def same_bits(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind in "fiub":
        return a.tobytes() == b.tobytes()
    return bool(np.all(a == b))


def main():
    one, other, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
    problems = []
    # Sums over particles whose order depends on the decomposition.
    summed = ("bin_sums", "fields/grid/sums", "fields/profile/sums",
              "observables/kinetic_energy/value", "observables/temperature/value")
    for name in ("checkpoint.h5", "run.h5"):
        a, b = datasets(f"{one}/{name}"), datasets(f"{other}/{name}")
        if sorted(a) != sorted(b):
            problems.append(f"{name}: datasets {sorted(set(a) ^ set(b))} in one run only")
        compared = 0
        for key in sorted(set(a) & set(b)):
            if key.endswith(summed):
                x, y = np.asarray(a[key], float), np.asarray(b[key], float)
                scale = max(np.abs(x).max(initial=0), np.abs(y).max(initial=0), 1e-300)
                worst = np.abs(x - y).max(initial=0) / scale
                if x.shape != y.shape or worst > ROUNDING:
                    problems.append(f"{name}:{key} differs by {worst:.3g} of its largest value")
            elif not same_bits(a[key], b[key]):
                problems.append(f"{name}:{key} is not the same bit for bit")
            compared += 1
        print(f"{name}: {compared} datasets compared")
    summary = json.load(open(f"{other}/summary.json"))
    reference = json.load(open(f"{one}/summary.json"))
    # One process against one (a resumed run, tests/cli/full_disk.sh): no "processes".
    per_rank = [reference["particles_final"]]
    if ranks > 1:
        if summary["processes"]["count"] != ranks:
            problems.append(f"summary.json: processes.count is {summary['processes']['count']}")
        per_rank = summary["processes"]["particles_per_rank"]
        if len(per_rank) != ranks or sum(per_rank) != reference["particles_final"]:
            problems.append(f"summary.json: particles_per_rank {per_rank} against "
                            f"{reference['particles_final']} particles in one process")
    for key in ("particles_final", "inserted", "steps", "list_builds"):
        if summary.get(key) != reference.get(key):
            problems.append(f"summary.json: {key} {summary.get(key)} against {reference.get(key)}")
    too_short = []
    if ranks > 1:
        builds = summary.get("list_builds", 0)
        migrated = summary["processes"].get("migrated_per_rank")
        print(f"list builds: {builds}, particles migrated per rank: {migrated}, "
              f"slab cuts moved: {summary['processes'].get('rebalances')}")
        if builds < MIN_LIST_BUILDS:
            too_short.append(f"{builds} list builds, fewer than {MIN_LIST_BUILDS}")
        if migrated is None or sum(migrated) < MIN_MIGRATED:
            too_short.append(
                f"particles migrated per rank {migrated}, fewer than {MIN_MIGRATED} in all")
    for p in problems:
        print("DIFFERS:", p)
    for p in too_short:
        print("FAIL: the run is too short to test several processes:", p)
    print(f"particles per rank: {per_rank}")
    return 1 if problems or too_short else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""The device check's digests and comparisons (apps/bench/gpu_check.sh; docs/cuda.md,
"The device check").

  digest RUN_DIR          one JSON object: the final particle state's hash, counts,
                          energies, field-sum totals, e_eff per pair, particle-steps/s
  compare REFERENCE NOW   one line: how a run's digest compares with the host's

A comparison is "bitwise" when the final particle states are bitwise equal and every
number derived from the field sums agrees to round-off (relative 1e-9: the device adds
them in another order). Otherwise the trajectory has left the host's, which round-off
anywhere does to a granular gas within a few collision times, and the run is judged by
its statistics: particle counts within 2 %, the kinetic energy within 2 %, the field sums'
totals within 5 %, e_eff (a property of the contact law at dt, not of the trajectory)
within 1e-9. A run that misses these FAILs.
"""
import hashlib
import json
import sys

import h5py
import numpy

ROUND_OFF = 1e-9
TOLERANCE = {"counts": 0.02, "kinetic_energy": 0.02, "fields": 0.05}


def digest(run_dir):
    out = {}
    h = hashlib.sha256()
    with h5py.File(f"{run_dir}/checkpoint.h5", "r") as f:
        for name, item in sorted(f["state"].items()):
            h.update(name.encode())
            h.update(numpy.ascontiguousarray(item[()]).tobytes())
    out["state"] = h.hexdigest()[:32]
    with h5py.File(f"{run_dir}/run.h5", "r") as f:
        series = f["observables"]
        out["kinetic_energy"] = float(series["kinetic_energy/value"][-1])
        out["contacts"] = int(series["contacts/value"][-1])
        totals = {}
        for path in ("fields/grid/sums", "fields/profile/sums"):
            if path in f:
                sums = f[path][()]
                totals[path] = sums.reshape(-1, sums.shape[-1]).sum(axis=0).tolist()
        out["field_totals"] = totals
    with open(f"{run_dir}/summary.json") as f:
        summary = json.load(f)
    for key in ("particles_final", "inserted", "deleted", "list_builds", "particle_steps_per_second"):
        out[key] = summary.get(key)
    out["e_eff"] = {f"{pair} {speed}": value["e_eff"]
                    for pair, speeds in sorted(summary["effective_restitution_at_dt"].items())
                    for speed, value in sorted(speeds.items()) if isinstance(value, dict)}
    return out


def relative(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def compare(ref, now):
    """Returns (status, text)."""
    worst_fields = 0.0
    for path, totals in ref["field_totals"].items():
        other = now["field_totals"].get(path)
        if other is None or len(other) != len(totals):
            return "FAIL", f"{path} missing or reshaped"
        scale = max(abs(t) for t in totals) or 1.0
        for a, b in zip(totals, other):
            worst_fields = max(worst_fields, abs(a - b) / max(abs(a), 1e-6 * scale))
    e_eff = max((relative(ref["e_eff"][p], now["e_eff"].get(p, float("nan")))
                 for p in ref["e_eff"] if isinstance(ref["e_eff"][p], float)), default=0.0)
    counts = max(relative(ref[k], now[k]) for k in ("particles_final", "inserted"))
    energy = relative(ref["kinetic_energy"], now["kinetic_energy"])
    numbers = (f"N {now['particles_final']} (host {ref['particles_final']}), "
               f"KE {energy:.1e}, fields {worst_fields:.1e}, e_eff {e_eff:.1e}")
    if not e_eff <= ROUND_OFF:
        return "FAIL", f"e_eff differs: {numbers}"
    if now["state"] == ref["state"]:
        if worst_fields <= ROUND_OFF and energy <= ROUND_OFF and counts == 0:
            return "ok", f"bitwise; fields to round-off ({numbers})"
        return "FAIL", f"same final state, yet {numbers}"
    within = (counts <= TOLERANCE["counts"] and energy <= TOLERANCE["kinetic_energy"]
              and worst_fields <= TOLERANCE["fields"])
    return ("ok" if within else "FAIL"), f"trajectory left the host's; {numbers}"


def main(argv):
    if len(argv) == 3 and argv[1] == "digest":
        json.dump(digest(argv[2]), sys.stdout, indent=1, sort_keys=True)
        sys.stdout.write("\n")
        return 0
    if len(argv) == 4 and argv[1] == "compare":
        with open(argv[2]) as f:
            ref = json.load(f)
        with open(argv[3]) as f:
            now = json.load(f)
        status, text = compare(ref, now)
        print(f"{status}: {text}")
        return 0 if status == "ok" else 1
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))

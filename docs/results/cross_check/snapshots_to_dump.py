#!/usr/bin/python3
"""Writes the particle snapshots of a granshock run's production window (RUN_DIR/run.h5,
/particles/all, docs/output_format.md) as a LAMMPS `dump custom` (id type x y z vx vy vz,
types 1 and 2 = the scene's species in order, z and vz zero), and the map for
`granshock fields --from-dump lammps` (the run's resolved scene plus a [dump] table,
docs/fields.md section 13). The same map, with the same analysis, reads LAMMPS' dump of
the same scene (run_lammps.sh).

Usage: snapshots_to_dump.py RUN_DIR OUT.dump OUT_MAP.toml
"""
import sys

import h5py


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    run_dir, out, map_out = sys.argv[1:]
    with h5py.File(f"{run_dir}/run.h5", "r") as f:
        resolved = f["scene/resolved"][()]
        resolved = resolved.decode() if isinstance(resolved, bytes) else resolved
        import tomllib
        scene = tomllib.loads(resolved)
        dt = scene["time"]["dt"]
        start, end = scene["time"]["production_start"], scene["time"]["duration"]
        width, length = scene["domain"]["width"], scene["domain"]["length"]
        r = scene["species"][0]["diameter"] / 2
        times = f["particles/all/count/time"][()]
        counts = f["particles/all/count/value"][()]
        frames = 0
        with open(out, "w") as o:
            first, last = round(start / dt), round(end / dt)
            for k, t in enumerate(times):
                if not (first <= round(t / dt) < last):  # the window on the step grid
                    continue
                n = int(counts[k])
                x = f["particles/all/position/value"][k, :n]
                v = f["particles/all/velocity/value"][k, :n]
                sp = f["particles/all/species/value"][k, :n]
                ids = f["particles/all/id/value"][k, :n]
                o.write(f"ITEM: TIMESTEP\n{round(t / dt)}\nITEM: NUMBER OF ATOMS\n{n}\n"
                        f"ITEM: BOX BOUNDS pp ff pp\n0 {width!r}\n0 {length!r}\n{-r!r} {r!r}\n"
                        "ITEM: ATOMS id type x y z vx vy vz\n")
                o.write("".join(f"{ids[i] + 1} {sp[i] + 1} {x[i, 0]!r} {x[i, 1]!r} 0 "
                                f"{v[i, 0]!r} {v[i, 1]!r} 0\n" for i in range(n)))
                frames += 1
    names = [s["name"] for s in scene["species"]]
    with open(map_out, "w") as m:
        m.write(f"# granshock fields --from-dump map: the resolved scene of {scene['scene']['name']}"
                " (docs/results/cross_check/snapshots_to_dump.py)\n")
        m.write(resolved + f"\n[dump]\ndt = {dt!r}\nflow_start = 0.0\n\n[dump.types]\n" +
                "".join(f'{i} = "{n}"\n' for i, n in enumerate(names, 1)))
    print(f"{frames} frames in [{start}, {end}) s", file=sys.stderr)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The gas each code delivers to the shock, and the particles that come back from it
(README.md here, "The remaining difference at D = 10 d"), from LAMMPS dumps read with
the cross-check's map (docs/fields.md section 13: the resolved scene and its [dump]
table).

Usage: stream_profiles.py MAP.toml [--every N] LABEL=DUMP [LABEL=DUMP ...]

Prints two Markdown tables per dump, over every N-th frame (default 10) of the map's
production window:
- along the channel (slabs of y over the whole width): phi, the mean velocity along the
  flow <v_y>/U and the variance of v_y over U^2;
- on the stagnation strip (|x - x_c| < 2 d) in 1 d bins of distance from the cylinder's
  face: particles per frame, <v_y>/U, and the fraction moving upstream (v_y < 0), of all
  and of each species: the particles the shock layer sends back into the stream.
"""
import bisect
import math
import sys
import tomllib

CHANNEL_EDGES_D = [0, 2, 4, 6, 10, 20, 40, 80, 120, 160, 200]
STRIP_HALF_WIDTH_D = 2.0
STRIP_BINS = 12


def frames(path, dump, start, every):
    """Yields (columns, rows) of every `every`-th frame at time >= start (a frame's time
    is the map's flow_start + TIMESTEP dt)."""
    with open(path) as f:
        k = 0
        while True:
            line = f.readline()
            if not line:
                return
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(f.readline())
            f.readline()
            n = int(f.readline())
            for _ in range(4):
                f.readline()
            columns = f.readline().split()[2:]
            rows = [f.readline() for _ in range(n)]
            if dump["flow_start"] + step * dump["dt"] < start - 0.5 * dump["dt"]:
                continue
            if k % every == 0:
                yield {c: i for i, c in enumerate(columns)}, rows
            k += 1


def face_and_edges(scene):
    """The cylinder's upstream face (y) and the channel's slab edges (m) upstream of it."""
    d = scene["units"]["d"]
    face = scene["obstacle"]["centre"][1] - scene["obstacle"]["diameter"] / 2
    return face, [e * d for e in CHANNEL_EDGES_D if e * d < face]


def profiles(path, scene, every):
    """Sums over the frames: per channel slab [n, sum v_y, sum v_y^2]; per strip bin n,
    sum v_y and the counts moving upstream, of all and per species."""
    d = scene["units"]["d"]
    xc = scene["obstacle"]["centre"][0]
    face, edges = face_and_edges(scene)
    types = {int(t): name for t, name in scene["dump"]["types"].items()}
    names = [s["name"] for s in scene["species"]]
    channel = [[0, 0.0, 0.0] for _ in edges[:-1]]
    strip = [{"n": 0, "vy": 0.0, "back": 0, **{f"n_{s}": 0 for s in names},
              **{f"back_{s}": 0 for s in names}} for _ in range(STRIP_BINS)]
    count = 0
    for col, rows in frames(path, scene["dump"], scene["time"]["production_start"], every):
        count += 1
        ix, iy, ivy, it = col["x"], col["y"], col["vy"], col["type"]
        for row in rows:
            p = row.split()
            x, y, vy = float(p[ix]), float(p[iy]), float(p[ivy])
            b = bisect.bisect_right(edges, y) - 1
            if 0 <= b < len(channel):
                c = channel[b]
                c[0] += 1
                c[1] += vy
                c[2] += vy * vy
            dist = (face - y) / d
            if abs(x - xc) < STRIP_HALF_WIDTH_D * d and 0 <= dist < STRIP_BINS:
                s = strip[int(dist)]
                species = types[int(p[it])]
                s["n"] += 1
                s[f"n_{species}"] += 1
                s["vy"] += vy
                if vy < 0:
                    s["back"] += 1
                    s[f"back_{species}"] += 1
    return count, channel, strip


def table(label, scene, result):
    count, channel, strip = result
    d, width, u = scene["units"]["d"], scene["domain"]["width"], scene["inflow"]["velocity"]
    _, edges = face_and_edges(scene)
    names = [s["name"] for s in scene["species"]]
    disc = math.pi * (d / 2) ** 2  # the discs' area: phi in the plane (scene.dim = 2)
    print(f"{label}: {count} frames\n")
    print("| y from the inlet (d) | phi | <v_y>/U | var v_y / U^2 |")
    print("|---|---|---|---|")
    for b, (n, s1, s2) in enumerate(channel):
        mean = s1 / n
        phi = n / count * disc / ((edges[b + 1] - edges[b]) * width)
        print(f"| {edges[b] / d:.0f}-{edges[b + 1] / d:.0f} | {phi:.4f} | {mean / u:.4f} "
              f"| {(s2 / n - mean * mean) / u ** 2:.5f} |")
    print()
    species = " | ".join(f"moving upstream, {s}" for s in names)
    print(f"| distance from the face (d) | particles per frame | <v_y>/U | moving upstream | {species} |")
    print("|---|---|---|---|" + "---|" * len(names))
    for b, s in enumerate(strip):
        if s["n"] == 0:
            continue
        per = " | ".join(f"{s[f'back_{n}'] / s[f'n_{n}']:.4f}" if s[f"n_{n}"] else "n/a"
                         for n in names)
        print(f"| {b}-{b + 1} | {s['n'] / count:.2f} | {s['vy'] / s['n'] / u:.3f} "
              f"| {s['back'] / s['n']:.4f} | {per} |")
    print()


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1], "rb") as f:
        scene = tomllib.load(f)
    args = argv[2:]
    every = 10
    if args[0] == "--every":
        every, args = int(args[1]), args[2:]
    for arg in args:
        label, path = arg.split("=", 1)
        table(label, scene, profiles(path, scene, every))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

"""The cost model of docs/scaling.md: time per step of one rank of N, slabs (along x or y:
the scenes here are square, so both give the same terms).

    T(N) = c_p * n / N * (1 + imbalance)              compute on the rank's particles
         + a_h + b_h * g                                halo: per exchange + per ghost
         + a_r * ceil(log2 N)                           the per-step global maximum
         + (c_sort + c_x) * ncell / k                   the global cell grid, per rebuild
    g = 2 * (particles per cell row)                    two boundary rows, any N
    E(N) = c_p * n / (N * T(N))                         parallel efficiency

Two layouts that are not built are projected beside it, to say whether they would pay: a
cell grid of the rank's own part and its halo only (ncell shrinks with N), and a 2-D
process grid of px x py ranks (g = 2 rows of the subdomain's width + 2 columns of its
height + 4 corner cells; eight neighbours, so six more messages per exchange).

Constants measured on this machine (2 cores, Open MPI's shared memory) are read from
measured.json; the network's latency and bandwidth, which this machine cannot measure,
are stated assumptions (NETWORK below). Prints Markdown tables: the model against the
measured 2-rank points, then the projections. Usage: /usr/bin/python3 model.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
M = json.load(open(os.path.join(HERE, "measured.json")))

# Assumed for a cluster (InfiniBand HDR class): a neighbour round trip of 3 us plus bytes
# over 10 GB/s, and 2 us per level of a tree allreduce. Not measured here.
NETWORK = {"round_trip_s": 3e-6, "bytes_per_s": 10e9, "allreduce_level_s": 2e-6}
BYTES_PER_GHOST_STEP = 32  # x and v, 2 doubles each (frictionless; +8 with spin)
# Assumed: each message beyond a slab's two costs 0.5 us more (posting, matching), so a
# 2-D grid's exchange with eight neighbours costs 3 us more than a slab's. Not measured.
EXTRA_MESSAGE_S = 0.5e-6


def scene(width_d, length_d, phi, shocked_factor=2.0):
    """Particles, cell rows and columns, and particles per row of a box at phi (1 d
    spheres, cell = 1.3 d); rows near the shock hold about shocked_factor times more."""
    cell = 1.3
    per_area = phi / (math.pi / 4)
    rows, cols = int(length_d / cell), int(width_d / cell)
    return {
        "n": per_area * width_d * length_d,
        "rows": rows,
        "cols": cols,
        "ncell": rows * cols,
        "per_row": per_area * width_d * cell * shocked_factor,
        "per_cell": per_area * cell * cell * shocked_factor,
    }


def process_grid(ranks):
    """The most nearly square px x py = ranks."""
    px = max(d for d in range(1, int(math.isqrt(ranks)) + 1) if ranks % d == 0)
    return px, ranks // px


def fits(s, ranks, layout):
    """Whether every subdomain is at least one cell row (and column) wide."""
    if layout == "grid2d":
        px, py = process_grid(ranks)
        return px <= s["cols"] and py <= s["rows"]
    return ranks <= s["rows"]


def step_time(s, ranks, network, layout="slabs", local_grid=False):
    c = M["constants"]
    extra_messages = 0
    if layout == "grid2d":
        px, py = process_grid(ranks)
        g = (2 * s["per_cell"] * (s["cols"] / px) + 2 * s["per_cell"] * (s["rows"] / py)
             + 4 * s["per_cell"])
        own_cells = (s["cols"] / px + 2) * (s["rows"] / py + 2)
        extra_messages = 6
    else:
        g = 2 * s["per_row"]
        own_cells = s["cols"] * (s["rows"] / ranks + 2)
    compute = c["compute_s_per_particle_step"] * s["n"] / ranks * (1 + c["imbalance"])
    if network:
        halo = (NETWORK["round_trip_s"] + extra_messages * EXTRA_MESSAGE_S
                + c["halo_pack_s_per_ghost"] * g + g * BYTES_PER_GHOST_STEP / NETWORK["bytes_per_s"])
        reduce = NETWORK["allreduce_level_s"] * math.ceil(math.log2(max(ranks, 2)))
    else:
        halo = c["halo_fixed_s"] + c["halo_s_per_ghost"] * g
        reduce = c["allreduce_s"]
    ncell = own_cells if local_grid else s["ncell"]
    grid = ((c["cell_sort_s_per_cell"] + c["exchange_s_per_cell"]) * ncell
            / c["steps_per_rebuild"])
    return compute, halo, reduce, grid


def efficiency(s, ranks, network=True, layout="slabs", local_grid=False):
    parts = step_time(s, ranks, network, layout, local_grid)
    ideal = M["constants"]["compute_s_per_particle_step"] * s["n"] / ranks
    return ideal / sum(parts), parts


def main():
    print("The model's terms against the measured 2-rank points (shared memory, this "
          "machine; compute from each run's own compute share):\n")
    print("| scene | wall per step measured | model | halo measured / model "
          "| exchange at rebuilds measured / model (global grid) |")
    print("|---|---|---|---|---|")
    c = M["constants"]
    for p in M["points"]:
        wall = p["wall_s_per_step"]
        compute = p["compute_share"] * wall
        halo = c["halo_fixed_s"] + c["halo_s_per_ghost"] * p["ghosts_per_rank"]
        # The cell sort's share of the global grid is inside the measured compute.
        grid = c["exchange_s_per_cell"] * p["ncell"] / p["steps_per_rebuild"]
        model = compute + halo + grid + p["per_step_max_share"] * wall
        print(f"| {p['name']} | {wall * 1e6:.1f} us | {model * 1e6:.1f} us | "
              f"{p['halo_share'] * wall * 1e6:.2f} / {halo * 1e6:.2f} us | "
              f"{p['rebuild_exchange_share'] * wall * 1e6:.2f} / {grid * 1e6:.2f} us |")
    cases = [("paper case (500 d x 500 d, 31,600 particles)", scene(500, 500, 0.1)),
             ("100x channel (5,000 d x 5,000 d, 3.2 million)", scene(5000, 5000, 0.1))]
    print("\nProjected parallel efficiency on a cluster (slabs along y; a slab is at least "
          "one cell row):\n")
    ranks = [2, 8, 64, 256, 1024, 4096]
    print("| scene | rows | " + " | ".join(f"{r} ranks" for r in ranks) + " |")
    print("|---|---|" + "---|" * len(ranks))
    for name, s in cases:
        cells = []
        for r in ranks:
            if r > s["rows"]:
                cells.append(f"- (> {s['rows']} rows)")
                continue
            e, _ = efficiency(s, r)
            cells.append(f"{e:.0%}")
        print(f"| {name} | {s['rows']} | " + " | ".join(cells) + " |")
    print("\nWhere a step's time goes at 64 and 1024 ranks (microseconds: compute, halo, "
          "allreduce, global grid scan):\n")
    for name, s in cases:
        for r in (64, 1024):
            if r > s["rows"]:
                continue
            e, parts = efficiency(s, r)
            print(f"- {name}, {r} ranks: " + ", ".join(f"{p * 1e6:.1f}" for p in parts)
                  + f" (efficiency {e:.0%})")
    print("\nDoes another layout pay? Efficiency by layout (built: slabs with the global grid; "
          "the others are projections of layouts not built):\n")
    layouts = [("slabs, global cell grid (built)", "slabs", False),
               ("slabs, local cell grid", "slabs", True),
               ("2-D process grid, global cell grid", "grid2d", False),
               ("2-D process grid, local cell grid", "grid2d", True)]
    print("| scene | layout | " + " | ".join(f"{r} ranks" for r in ranks) + " |")
    print("|---|---|" + "---|" * len(ranks))
    for name, s in cases:
        for label, layout, local in layouts:
            cells = [f"{efficiency(s, r, True, layout, local)[0]:.0%}" if fits(s, r, layout)
                     else "-" for r in ranks]
            print(f"| {name} | {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Checks the run.h5 / checkpoint.h5 layout of docs/output_format.md as h5py sees it.

Usage: check_run_file.py DIR   (DIR as written by write_sample_run: run.h5 in 2-D with
friction and frames of 5, 12, 0, 3 particles, run3d.h5 in 3-D without friction with 4, 2,
and checkpoint.h5)
"""
import os
import sys

import h5py
import numpy as np

failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def check_run(path, dim, counts, species_radius, spin):
    frames, n_max = len(counts), max(counts)
    with h5py.File(path, "r") as f:
        expect(int(f.attrs["granshock_format_version"]) == 3, f"{path}: format version")
        expect(list(f["h5md"].attrs["version"]) == [1, 1], f"{path}: /h5md version")
        expect(text(f["h5md/creator"].attrs["name"]) == "granshock", f"{path}: creator name")
        expect("version" in f["h5md/creator"].attrs, f"{path}: creator version")
        expect(text(f["h5md/author"].attrs["name"]) == "granshock", f"{path}: author name")
        run_id = text(f.attrs["run_id"]) if "run_id" in f.attrs else ""
        expect(len(run_id) == 32 and all(c in "0123456789abcdef" for c in run_id),
               f"{path}: @run_id '{run_id}' is not 32 hex digits")
        expect(text(f["scene/as_given"][()]).startswith("# as given"), f"{path}: scene as given")
        expect(text(f["scene/resolved"][()]).startswith("# resolved"), f"{path}: scene resolved")
        expect(int(f["particles/all/box"].attrs["dimension"]) == dim, f"{path}: box dimension")

        all_ = f["particles/all"]
        for name in ("position", "velocity"):
            value = all_[name + "/value"]
            expect(value.shape == (frames, n_max, dim), f"{path}: {name} shape {value.shape}")
            expect(value.dtype == np.float64, f"{path}: {name} dtype {value.dtype}")
            expect(value.maxshape == (None, None, dim), f"{path}: {name} maxshape {value.maxshape}")
            expect(np.isnan(value.fillvalue), f"{path}: {name} fill value")
            data = value[()]
            for frame, n in enumerate(counts):
                expect(not np.isnan(data[frame, :n]).any(), f"{path}: {name} frame {frame} has NaN")
                expect(np.isnan(data[frame, n:]).all(), f"{path}: {name} frame {frame} not NaN past n")
        for name in ("species", "id"):
            value = all_[name + "/value"]
            expect(value.shape == (frames, n_max), f"{path}: {name} shape {value.shape}")
            expect(value.dtype == np.int32, f"{path}: {name} dtype {value.dtype}")
            expect(value.fillvalue == -1, f"{path}: {name} fill value")
            data = value[()]
            for frame, n in enumerate(counts):
                expect((data[frame, :n] >= 0).all(), f"{path}: {name} frame {frame} values")
                expect((data[frame, n:] == -1).all(), f"{path}: {name} frame {frame} past n")
        # Format 2: radius (from the species) and, with friction, the spin about z.
        expect(list(f["parameters/species_radius"][()]) == species_radius, f"{path}: species_radius")
        unit = f["parameters/species_radius"].attrs.get("unit")
        expect((unit.decode() if isinstance(unit, bytes) else unit) == "m",
               f"{path}: species_radius has no unit attribute 'm' ({unit!r})")
        elements = ["radius"] + (["angular_velocity"] if spin else [])
        expect(("angular_velocity" in all_) == spin, f"{path}: angular_velocity present")
        species = all_["species/value"][()]
        for name, unit in (("radius", "m"), ("angular_velocity", "rad s-1")):
            if name not in elements:
                continue
            value = all_[name + "/value"]
            expect(value.shape == (frames, n_max), f"{path}: {name} shape {value.shape}")
            expect(value.dtype == np.float64, f"{path}: {name} dtype {value.dtype}")
            expect(value.maxshape == (None, None), f"{path}: {name} maxshape {value.maxshape}")
            expect(text(value.attrs["unit"]) == unit, f"{path}: {name} unit")
            data = value[()]
            for frame, n in enumerate(counts):
                expect(np.isnan(data[frame, n:]).all(), f"{path}: {name} frame {frame} not NaN past n")
                if name == "radius":
                    expect(np.array_equal(data[frame, :n], np.array(species_radius)[species[frame, :n]]),
                           f"{path}: radius frame {frame} is not its species'")
                else:
                    expect(not np.isnan(data[frame, :n]).any(), f"{path}: {name} frame {frame} has NaN")
        # The views run.xmf reads (io/frame_views.hpp): one group per frame.
        expect(sorted(f["xdmf"]) == sorted([f"frame_{k:06d}" for k in range(frames)] + ["vertex_index"]),
               f"{path}: /xdmf holds {sorted(f['xdmf'])}")
        steps = [1000 * (i + 1) for i in range(frames)]
        for name in ["position", "velocity", "species", "id", "count"] + elements:
            expect(list(all_[name + "/step"][()]) == steps, f"{path}: {name}/step")
            expect(np.allclose(all_[name + "/time"][()], [1e-3 * (i + 1) for i in range(frames)]),
                   f"{path}: {name}/time")
        expect(list(all_["count/value"][()]) == counts, f"{path}: count/value")
        expect(text(all_["position/value"].attrs["unit"]) == "m", f"{path}: position unit")
        expect(text(all_["velocity/value"].attrs["unit"]) == "m s-1", f"{path}: velocity unit")

        names = ["particles", "kinetic_energy", "temperature", "contacts", "inserted",
                 "deleted_outlet", "deleted_inlet"]
        expect(sorted(f["observables"].keys()) == sorted(names), f"{path}: observables {list(f['observables'])}")
        for name in names:
            group = f["observables/" + name]
            expect(group["value"].shape == (frames,), f"{path}: {name} shape")
            expect(list(group["step"][()]) == steps, f"{path}: {name}/step")
            expect(group["time"].shape == (frames,), f"{path}: {name}/time")
        expect(list(f["observables/particles/value"][()]) == counts, f"{path}: particles values")
        expect(f["observables/kinetic_energy/value"].dtype == np.float64, f"{path}: energy dtype")
        expect(f["observables/contacts/value"].dtype == np.int64, f"{path}: contacts dtype")
        expect(f["fields/bin_sums"].shape == (2, 3), f"{path}: fields/bin_sums")
        expect(float(f["summary"].attrs["mach_measured"]) == 4.9, f"{path}: summary attribute")


MASK = (1 << 64) - 1
K1, K2, K3 = 0x9E3779B185EBCA87, 0xC2B2AE3D27D4EB4F, 0x165667B19E3779F9


def rotl(x, r):
    return ((x << r) | (x >> (64 - r))) & MASK


def gshash64(data):
    """The checkpoint hash as docs/output_format.md describes it (io/file_hash.cpp)."""
    def round_(lane, word):
        return rotl((lane + word * K2) & MASK, 31) * K1 & MASK
    lanes = [(K1 + K2) & MASK, K2, 0, (-K1) & MASK]
    full = len(data) - len(data) % 32
    words = np.frombuffer(data[:full], dtype="<u8").tolist()
    for at in range(0, len(words), 4):
        lanes = [round_(lane, w) for lane, w in zip(lanes, words[at:at + 4])]
    h = (rotl(lanes[0], 1) + rotl(lanes[1], 7) + rotl(lanes[2], 12) + rotl(lanes[3], 18)) & MASK
    tail = data[full:] + bytes(-len(data[full:]) % 8)
    for w in np.frombuffer(tail, dtype="<u8").tolist():
        h = (rotl(h ^ round_(0, w), 27) * K1 + K3) & MASK
    h ^= len(data) * K3 & MASK
    for shift, factor in ((33, 0xFF51AFD7ED558CCD), (33, 0xC4CEB9FE1A85EC53)):
        h = (h ^ (h >> shift)) * factor & MASK
    return h ^ (h >> 33)


def check_checkpoint_header(path):
    with open(path, "rb") as f:
        raw = f.read()
    block, body = raw[:512], raw[512:]
    text = block.rstrip(b"\0").decode()
    lines = text.splitlines()
    expect(lines[:2] == ["granshock checkpoint", "format_version 4"], f"{path}: header {lines}")
    expect(lines[2] == f"hashed_bytes {len(body)}", f"{path}: hashed_bytes")
    expect(lines[3] == f"hash {gshash64(body):016x}", f"{path}: hash")
    head = text[:text.rindex("header_hash ")].encode()
    expect(lines[4] == f"header_hash {gshash64(head):016x}", f"{path}: header_hash")


def check_checkpoint(path):
    check_checkpoint_header(path)
    with h5py.File(path, "r") as f:
        expect(f.userblock_size == 512, f"{path}: user block {f.userblock_size}")
        expect(text(f.attrs["granshock_file"]) == "checkpoint", f"{path}: granshock_file")
        state = f["state"]
        for name in ("dim", "step", "next_id", "history_slots", "list_builds"):
            expect(name in state.attrs, f"{path}: /state@{name}")
        shapes = {"position": (3, 2), "velocity": (3, 2), "force": (3, 2),
                  "angular_velocity": (3,), "torque": (3,), "species": (3,), "id": (3,),
                  "history_partner": (3, 2), "history_spring": (3, 2, 2),
                  "history_obstacle_spring": (3, 2), "reference_position": (3, 2),
                  "neighbour_offsets": (4,), "neighbours": (3,)}
        for name, shape in shapes.items():
            expect(state[name].shape == shape, f"{path}: /state/{name} shape {state[name].shape}")
        expect(list(state.attrs["removed_high"]) == [0, 5, 0], f"{path}: /state@removed_high")
        expect(list(state.attrs["removed_low"]) == [0, 2, 0], f"{path}: /state@removed_low")
        run = f["run"]
        for name in ("rng_counter", "inserted", "deleted_outlet", "deleted_inlet",
                     "insertion_carry", "wall_seconds_so_far", "cpu_seconds_so_far"):
            expect(name in run.attrs, f"{path}: /run@{name}")
        expect(run.attrs["rng_counter"].dtype == np.uint64, f"{path}: rng_counter dtype")
        expect(list(run["bin_shape"][()]) == [2, 3, 1], f"{path}: bin_shape")
        expect(run["bin_sums"].shape == (6,), f"{path}: bin_sums")
        expect(text(f["scene/resolved"][()]).startswith("# resolved"), f"{path}: scene")


def main():
    directory = sys.argv[1]
    check_run(os.path.join(directory, "run.h5"), 2, [5, 12, 0, 3], [0.5e-3, 0.6e-3, 0.75e-3], True)
    check_run(os.path.join(directory, "run3d.h5"), 3, [4, 2], [1e-3, 1e-3, 2e-3], False)
    check_checkpoint(os.path.join(directory, "checkpoint.h5"))
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        return 1
    print("run.h5, run3d.h5 and checkpoint.h5 match docs/output_format.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())

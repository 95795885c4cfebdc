#!/usr/bin/python3
"""Checks that run.xmf parses as XML, lists every frame of run.h5 that has particles with
its time, and that every DataItem names a dataset of the .h5 with the declared shape and
type, holding exactly that frame's particles: the frame's rows of the H5MD element it
views, vectors padded with z = 0, the vertex cells 0 .. n-1 (docs/output_format.md, "run.xmf").

Usage: check_xdmf.py FILE.xmf EXPECTED_GRIDS
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)


def dims(text):
    return tuple(int(x) for x in text.split())


def check_item(f, item, frame, n, element):
    """One DataItem of the grid of `frame` (n particles) that views `element`."""
    file_name, dataset = item.text.strip().split(":", 1)
    what = f"frame {frame} {dataset}"
    expect(item.get("Format") == "HDF", f"{what}: Format")
    expect(dataset == f"/xdmf/frame_{frame:06d}/{element}", f"{what}: not the frame's view")
    if dataset not in f:
        expect(False, f"{what}: missing")
        return
    data = f[dataset]
    declared = dims(item.get("Dimensions"))
    expect(declared == data.shape, f"{what}: declared {declared}, stored {data.shape}")
    expect(data.shape[0] == n, f"{what}: {data.shape[0]} rows, the grid has {n}")
    kind = "Float" if data.dtype.kind == "f" else "Int"
    expect(item.get("NumberType") == kind, f"{what}: NumberType")
    expect(int(item.get("Precision")) == data.dtype.itemsize, f"{what}: Precision")
    values = data[()]
    if element == "vertex":
        expect(np.array_equal(values, np.arange(n)), f"{what}: not 0 .. n-1")
        return
    stored = f[f"particles/all/{element}/value"][frame, :n]
    if values.ndim == 2 and values.shape[1] > stored.shape[-1]:
        width = stored.shape[-1]
        expect(not values[:, width:].any(), f"{what}: padding is not 0")
        values = values[:, :width]
    expect(np.array_equal(values, stored), f"{what}: differs from the frame's rows")
    if kind == "Float":
        expect(not np.isnan(values).any(), f"{what}: reaches fill values")
    else:
        expect((values >= 0).all(), f"{what}: reaches fill values")


def check_obstacle(grid, frame):
    """The obstacle's grid of a frame: one closed polygon whose points the file holds."""
    if grid is None:
        return
    topology, geometry = grid.find("Topology"), grid.find("Geometry/DataItem")
    n = int(topology.get("NodesPerElement"))
    expect(topology.get("TopologyType") == "Polygon" and topology.get("NumberOfElements") == "1",
           f"frame {frame}: the obstacle is not one polygon")
    expect(list(map(int, topology.find("DataItem").text.split())) == list(range(n)),
           f"frame {frame}: the obstacle's cell is not its points in order")
    points = np.array(geometry.text.split(), dtype=float).reshape(dims(geometry.get("Dimensions")))
    expect(geometry.get("Format") == "XML" and points.shape[0] == n >= 3,
           f"frame {frame}: the obstacle's {points.shape[0]} points for a polygon of {n}")


def main():
    xmf, expected_grids = sys.argv[1], int(sys.argv[2])
    base = os.path.dirname(os.path.abspath(xmf))
    text = open(xmf).read()
    root = ET.fromstring(text)  # raises on malformed XML
    expect("HyperSlab" not in text, "a HyperSlab: ParaView's Xdmf3 readers cannot read it")
    expect(root.tag == "Xdmf" and root.get("Version") == "2.0", "root element")
    collection = root.find("Domain/Grid")
    expect(collection is not None and collection.get("CollectionType") == "Temporal",
           "temporal collection")
    grids = collection.findall("Grid")
    expect(len(grids) == expected_grids, f"{len(grids)} grids, expected {expected_grids}")
    h5_name = next(i for i in root.iter("DataItem") if i.get("Format") == "HDF").text.split(":")[0]
    items = 0
    with h5py.File(os.path.join(base, h5_name), "r") as f:
        counts = f["particles/all/count/value"][()]
        times = f["particles/all/count/time"][()]
        frames = [k for k, n in enumerate(counts) if n > 0]
        expect(len(grids) == len(frames), f"{len(grids)} grids, {len(frames)} frames with particles")
        for grid, frame in zip(grids, frames):
            n = int(counts[frame])
            expect(float(grid.find("Time").get("Value")) == times[frame], f"frame {frame}: time")
            if grid.get("CollectionType") == "Spatial":
                # With an obstacle: the frame holds the particles' grid and the obstacle's.
                parts = {g.get("Name"): g for g in grid.findall("Grid")}
                expect(sorted(parts) == ["obstacle", "particles"], f"frame {frame}: {sorted(parts)}")
                check_obstacle(parts.get("obstacle"), frame)
                grid = parts.get("particles", grid)
            topology = grid.find("Topology")
            expect(topology.get("TopologyType") == "Polyvertex", "Polyvertex topology")
            expect(int(topology.get("NumberOfElements")) == n, f"frame {frame}: NumberOfElements")
            if topology.find("DataItem") is None:
                expect(False, f"frame {frame}: no vertex cells (the Xdmf3 readers make none)")
                continue
            check_item(f, topology.find("DataItem"), frame, n, "vertex")
            check_item(f, grid.find("Geometry/DataItem"), frame, n, "position")
            for attribute in grid.findall("Attribute"):
                name = attribute.get("Name")
                item = attribute.find("DataItem")
                check_item(f, item, frame, n, name)
                vector = attribute.get("AttributeType") == "Vector"
                expect(len(dims(item.get("Dimensions"))) == (2 if vector else 1)
                       and (not vector or dims(item.get("Dimensions"))[1] == 3),
                       f"frame {frame} {name}: a Vector has 3 components, a Scalar 1")
                expect(attribute.get("Center") == "Node", f"frame {frame} {name}: Center")
            items += 2 + len(grid.findall("Attribute"))
            names = [a.get("Name") for a in grid.findall("Attribute")]
            expected = [m for m in ("species", "id", "velocity", "radius", "angular_velocity")
                        if m in f["particles/all"]]
            expect(names == expected, f"frame {frame}: attributes {names}, expected {expected}")
    expect(re.search(r"frame_\d{6}/", text) is not None, "no frame views")
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        return 1
    print(f"{xmf}: {len(grids)} grids, {items} data items, each exactly its frame's particles")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Checks that an XDMF file parses as XML and that every HyperSlab in it selects a valid
region of an existing dataset in the referenced .h5 file, with a matching type.

Usage: check_xdmf.py FILE.xmf EXPECTED_GRIDS
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def dims(text):
    return [int(x) for x in text.split()]


def main():
    xmf, expected_grids = sys.argv[1], int(sys.argv[2])
    base = os.path.dirname(os.path.abspath(xmf))
    root = ET.parse(xmf).getroot()  # raises on malformed XML
    failures = []

    def expect(condition, message):
        if not condition:
            failures.append(message)

    expect(root.tag == "Xdmf" and root.get("Version") == "2.0", "root element")
    collection = root.find("Domain/Grid")
    expect(collection is not None and collection.get("CollectionType") == "Temporal",
           "temporal collection")
    grids = collection.findall("Grid")
    expect(len(grids) == expected_grids, f"{len(grids)} grids, expected {expected_grids}")
    times = [float(g.find("Time").get("Value")) for g in grids]
    expect(times == sorted(times), "times increase")

    slabs = 0
    for grid in grids:
        n = int(grid.find("Topology").get("NumberOfElements"))
        expect(grid.find("Topology").get("TopologyType") == "Polyvertex", "Polyvertex topology")
        for slab in grid.iter("DataItem"):
            if slab.get("ItemType") != "HyperSlab":
                continue
            slabs += 1
            selection, source = slab.findall("DataItem")
            start, stride, count = np.array(dims(selection.text)).reshape(3, -1)
            file_name, dataset = source.text.strip().split(":", 1)
            with h5py.File(os.path.join(base, file_name), "r") as f:
                expect(dataset in f, f"{dataset} missing")
                if dataset not in f:
                    continue
                data = f[dataset]
                declared = tuple(dims(source.get("Dimensions")))
                expect(declared == data.shape, f"{dataset}: declared {declared}, stored {data.shape}")
                expect(len(start) == data.ndim, f"{dataset}: selection rank")
                last = start + (count - 1) * stride
                expect((start >= 0).all() and (last < np.array(data.shape)).all(),
                       f"{dataset}: selection {start} {count} outside {data.shape}")
                expect(np.prod(dims(slab.get("Dimensions"))) == np.prod(count),
                       f"{dataset}: result size")
                expect(count[1] == n, f"{dataset}: selects {count[1]} particles, grid has {n}")
                kind = "Float" if data.dtype.kind == "f" else "Int"
                expect(source.get("NumberType") == kind, f"{dataset}: NumberType")
                expect(int(source.get("Precision")) == data.dtype.itemsize, f"{dataset}: Precision")
                region = data[tuple(slice(s, s + c * d, d) for s, c, d in zip(start, count, stride))]
                if kind == "Float":
                    expect(not np.isnan(region).any(), f"{dataset}: selection reaches fill values")
                else:
                    expect((region >= 0).all(), f"{dataset}: selection reaches fill values")
    expect(slabs > 0, "no hyperslabs")
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        return 1
    print(f"{xmf}: {len(grids)} grids, {slabs} hyperslabs, all inside their datasets")
    return 0


if __name__ == "__main__":
    sys.exit(main())

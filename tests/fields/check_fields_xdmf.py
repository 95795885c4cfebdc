#!/usr/bin/python3
"""Checks fields.xmf (written by `granshock fields`) against its fields.h5 the way an
XDMF reader sees it: the XML parses, the grid is a 2DSMesh of (ny + 1) x (nx + 1) nodes
with XY geometry, and every DataItem names an existing dataset whose shape, number type
and precision match what the XML declares; every attribute is cell-centred on ny x nx
(x 3 for the Vectors, one of which is the mean velocity u).

Usage: check_fields_xdmf.py FIELDS_XMF
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py


def dims(text):
    return tuple(int(x) for x in text.split())


def main():
    xmf = sys.argv[1]
    base = os.path.dirname(os.path.abspath(xmf))
    root = ET.parse(xmf).getroot()
    failures = []

    def expect(condition, message):
        if not condition:
            failures.append(message)

    expect(root.tag == "Xdmf" and root.get("Version") == "2.0", "root element")
    grid = root.find("Domain/Grid")
    expect(grid is not None and grid.get("GridType") == "Uniform", "one uniform grid")
    topology = grid.find("Topology")
    expect(topology.get("TopologyType") == "2DSMesh", "2DSMesh topology")
    node_dims = dims(topology.get("Dimensions"))
    cell_dims = tuple(n - 1 for n in node_dims)
    expect(grid.find("Geometry").get("GeometryType") == "XY", "XY geometry")

    items = 0
    for item in grid.iter("DataItem"):
        items += 1
        file_name, dataset = item.text.strip().split(":", 1)
        with h5py.File(os.path.join(base, file_name), "r") as f:
            expect(dataset in f, f"{dataset} missing")
            if dataset not in f:
                continue
            data = f[dataset]
            declared = dims(item.get("Dimensions"))
            expect(declared == data.shape, f"{dataset}: declared {declared}, stored {data.shape}")
            kind = "Float" if data.dtype.kind == "f" else "Int"
            expect(item.get("NumberType") == kind, f"{dataset}: NumberType")
            expect(int(item.get("Precision")) == data.dtype.itemsize, f"{dataset}: Precision")
    geometry = dims(grid.find("Geometry/DataItem").get("Dimensions"))
    expect(geometry == node_dims + (2,), f"geometry {geometry} for nodes {node_dims}")
    attributes = grid.findall("Attribute")
    for attribute in attributes:
        expect(attribute.get("Center") == "Cell", f"{attribute.get('Name')}: cell-centred")
        # A Vector (the mean velocity u, u_s per species) has three components per cell.
        vector = attribute.get("AttributeType") == "Vector"
        expect(dims(attribute.find("DataItem").get("Dimensions")) == cell_dims + ((3,) if vector else ()),
               f"{attribute.get('Name')}: {cell_dims} cells")
    names = [a.get("Name") for a in attributes if a.get("AttributeType") == "Vector"]
    expect("u" in names, f"no mean velocity vector u (vectors: {names})")
    expect(len(attributes) >= 20, f"only {len(attributes)} attributes")
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        return 1
    print(f"{xmf}: {len(attributes)} cell attributes on {cell_dims[0]} x {cell_dims[1]} cells, "
          f"{items} data items, all present in their .h5")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Includes outside kernels/ show the layer of the header: "core/scene.hpp", not "scene.hpp".

A reader sees at the include which layer a file depends on (docs/design.md, "Layers").
Flagged, in every C++ file under core/, io/, analysis/, cases/, apps/, parallel/ and
tests/: an #include "NAME" whose NAME, without a directory, is a header of one of those
layers. Headers under kernels/ are included as "solver/dem_solver.hpp" (from kernels/);
generated headers (not in the tree) and the tests' own helpers are left alone.
Usage: includes_show_layer.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

from source_lines import report, source_lines

LAYERS = ["core", "io", "analysis", "cases", "apps", "parallel"]
SOURCES = {".cpp", ".hpp", ".h", ".inl", ".in"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"/]+)"')


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    layer_headers = {p.name for layer in LAYERS for p in (root / layer).rglob("*")
                     if p.suffix in {".hpp", ".h", ".inl"} and p.is_file()}
    found = []
    for path, number, line in source_lines(root, LAYERS + ["tests"], SOURCES):
        m = INCLUDE.match(line)
        if m and m.group(1) in layer_headers:
            found.append(f"{path}:{number}: {line.strip()}")
    return report(found, 'include(s) without their layer; write "core/x.hpp", "io/x.hpp", ...',
                  "every include outside kernels/ shows its layer")


if __name__ == "__main__":
    sys.exit(main())

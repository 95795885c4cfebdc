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

LAYERS = ["core", "io", "analysis", "cases", "apps", "parallel"]
SOURCES = {".cpp", ".hpp", ".h", ".inl", ".in"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"/]+)"')


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    layer_headers = {p.name for layer in LAYERS for p in (root / layer).rglob("*")
                     if p.suffix in {".hpp", ".h", ".inl"} and p.is_file()}
    found = []
    for layer in LAYERS + ["tests"]:
        for path in sorted((root / layer).rglob("*")):
            if path.suffix not in SOURCES or not path.is_file():
                continue
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                m = INCLUDE.match(line)
                if m and m.group(1) in layer_headers:
                    found.append(f"{path.relative_to(root)}:{number}: {line.strip()}")
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} include(s) without their layer; write \"core/x.hpp\", \"io/x.hpp\", ...")
        return 1
    print("every include outside kernels/ shows its layer")
    return 0


if __name__ == "__main__":
    sys.exit(main())

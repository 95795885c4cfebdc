#!/usr/bin/env python3
"""Every include of a granshock header is spelled from the repository's root, in every layer:
"core/scene.hpp", "kernels/solver/dem_solver.hpp", never "scene.hpp" or "solver/dem_solver.hpp";
and every include points down the layers (docs/design.md, "Layers"): a layer includes
itself and the layers MAY_INCLUDE names for it, never one above it.

A reader sees at the include which layer a file depends on (docs/design.md, "Layers"), and
one header has one spelling. Flagged, in every C++ file under core/, io/, analysis/,
cases/, apps/, parallel/, kernels/ and tests/: an #include "NAME" that names a header of
one of those layers other than as LAYER/PATH from the root (a bare name, or a path from
inside a layer such as "models/hertz.hpp"). Generated headers (not in the tree) and the
tests' own helpers are left alone.
Usage: includes_show_layer.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

from source_lines import report, source_lines

LAYERS = ["core", "models", "io", "analysis", "cases", "apps", "parallel", "kernels"]

# The layers each layer may include besides itself (docs/design.md, "Layers"). io and
# analysis are compiled without Kokkos, so they never see kernels/; the cases see the
# solver through core/solver.hpp and make_solver alone, never kernels/solver/. apps and
# tests see everything.
MAY_INCLUDE = {
    "core": set(),
    "models": {"core"},
    "parallel": {"core"},
    "kernels": {"models", "parallel", "core"},
    "io": {"models", "core"},
    "analysis": {"io", "models", "core"},
    "cases": {"analysis", "io", "kernels", "models", "parallel", "core"},
}
NOT_FROM_CASES = "kernels/solver/"
SOURCES = {".cpp", ".hpp", ".h", ".inl", ".in"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    headers = [p.relative_to(root) for layer in LAYERS for p in (root / layer).rglob("*")
               if p.suffix in {".hpp", ".h", ".inl"} and p.is_file()]
    # Every path by which a layer's header could be named other than from the root: its
    # name alone and each tail of its path ("models/hertz.hpp" of kernels/models/hertz.hpp).
    other_spellings = {}
    for h in headers:
        parts = h.parts
        for k in range(1, len(parts)):
            other_spellings.setdefault("/".join(parts[k:]), str(h))
    found = []
    for path, number, line in source_lines(root, LAYERS + ["tests"], SOURCES):
        m = INCLUDE.match(line)
        if not m:
            continue
        name = m.group(1)
        if name.split("/")[0] in LAYERS and (root / name).is_file():
            found.extend(points_up(path, number, line, name))
            continue
        if name in other_spellings:
            found.append(f"{path}:{number}: {line.strip()} (write \"{other_spellings[name]}\")")
    return report(found, "include(s) not spelled from the repository's root or pointing up a layer",
                  "every include of a granshock header is spelled from the root and points down")


def points_up(path, number, line, name):
    """The complaint about an include that points up a layer, if it does."""
    layer, target = path.parts[0], name.split("/")[0]
    if layer not in MAY_INCLUDE or target == layer:
        return []
    if target not in MAY_INCLUDE[layer]:
        return [f"{path}:{number}: {line.strip()} ({layer}/ may include "
                f"{', '.join(sorted(MAY_INCLUDE[layer])) or 'nothing'} besides itself)"]
    if layer == "cases" and name.startswith(NOT_FROM_CASES):
        return [f"{path}:{number}: {line.strip()} (the cases see the solver through "
                f"core/solver.hpp and make_solver)"]
    return []


if __name__ == "__main__":
    sys.exit(main())

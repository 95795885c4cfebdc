#!/usr/bin/env python3
"""The cases include each other without cycles (docs/design.md, "Layers"): neither between
their directories (bow_shock, study, tradeoff, accuracy, ...) nor between their modules
(a module is x.hpp with x.cpp). A cycle means neither side can be read, built or tested
without the other; cases/accuracy is the leaf that the run, the study and the tradeoff
share so that none of them includes another back.

Prints each cycle found as A -> B -> ... -> A.
Usage: cases_include_no_cycles.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"cases/([^"]+)\.hpp"')


def graph(root):
    """{module: {modules it includes}} for every module under cases/."""
    edges = {}
    for path in sorted((root / "cases").rglob("*")):
        if path.suffix not in {".cpp", ".hpp"} or not path.is_file():
            continue
        module = path.relative_to(root / "cases").with_suffix("").as_posix()
        targets = edges.setdefault(module, set())
        for line in path.read_text(errors="replace").splitlines():
            m = INCLUDE.match(line)
            if m and m.group(1) != module:
                targets.add(m.group(1))
    return edges


def cycles(edges):
    """Every elementary cycle's first sighting in a depth-first walk, as a list of nodes."""
    found, state, stack = [], {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == "open":
                found.append(stack[stack.index(nxt):] + [nxt])
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = "done"

    for node in sorted(edges):
        if node not in state:
            visit(node)
    return found


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    modules = graph(root)
    directories = {}
    for module, targets in modules.items():
        here = module.split("/")[0]
        directories.setdefault(here, set()).update(
            t.split("/")[0] for t in targets if t.split("/")[0] != here)
    problems = [("directories", c) for c in cycles(directories)]
    problems += [("modules", c) for c in cycles(modules)]
    for what, cycle in problems:
        print(f"cycle between {what}: {' -> '.join(cycle)}")
    if problems:
        print(f"{len(problems)} include cycle(s) under cases/")
        return 1
    print(f"no include cycle among {len(modules)} modules in {len(directories)} directories "
          "of cases/")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Code and test comments cite the repository's docs, never an issue number.

An issue number means nothing to a reader of the code once the issue is closed; the docs
(docs/*.md) say what the code does and why. Flagged, in every C++, CMake, shell and Python
file under core/, kernels/, io/, analysis/, cases/, apps/, tests/ and cmake/: "issue 11",
"Issue #11", "issue (3a)", "of the ... issue" and "IssueNN" (a test name built from one) and
"the data-safety issue".
Usage: comments_cite_docs.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

LAYERS = ["core", "kernels", "io", "analysis", "cases", "apps", "tests", "cmake"]
SUFFIXES = {".cpp", ".hpp", ".h", ".in", ".txt", ".cmake", ".sh", ".py"}
CITES_AN_ISSUE = re.compile(
    r"\b[Ii]ssue\s*#?\d+|\bIssue\d+\b|\bof the [\w\s-]{0,30}\bissue\b|\([\w\s-]*\bissue[,)]"
    r"|\b\w+-\w+ issues?\b")
# This file names the patterns it looks for.
SELF = pathlib.Path(__file__).resolve()


def offending_lines(root):
    for layer in LAYERS:
        for path in sorted((root / layer).rglob("*")):
            if path.suffix not in SUFFIXES and path.name != "CMakeLists.txt":
                continue
            if not path.is_file() or path.resolve() == SELF:
                continue
            text = path.read_text(errors="replace")
            for number, line in enumerate(text.splitlines(), 1):
                if CITES_AN_ISSUE.search(line):
                    yield f"{path.relative_to(root)}:{number}: {line.strip()}"


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    found = list(offending_lines(root))
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} line(s) cite an issue; cite docs/*.md instead")
        return 1
    print("no comment cites an issue")
    return 0


if __name__ == "__main__":
    sys.exit(main())

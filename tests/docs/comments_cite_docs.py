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

from source_lines import report, source_lines

LAYERS = ["core", "models", "kernels", "io", "analysis", "cases", "apps", "tests", "cmake"]
SUFFIXES = {".cpp", ".hpp", ".h", ".in", ".txt", ".cmake", ".sh", ".py"}
CITES_AN_ISSUE = re.compile(
    r"\b[Ii]ssue\s*#?\d+|\bIssue\d+\b|\bof the [\w\s-]{0,30}\bissue\b|\([\w\s-]*\bissue[,)]"
    r"|\b\w+-\w+ issues?\b")
# This file names the patterns it looks for.
SELF = pathlib.Path(__file__).resolve()


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    found = [f"{path}:{number}: {line.strip()}"
             for path, number, line in source_lines(root, LAYERS, SUFFIXES, {"CMakeLists.txt"}, SELF)
             if CITES_AN_ISSUE.search(line)]
    return report(found, "line(s) cite an issue; cite docs/*.md instead",
                  "no comment cites an issue")


if __name__ == "__main__":
    sys.exit(main())

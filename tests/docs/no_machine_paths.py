#!/usr/bin/env python3
"""Committed docs, scenes and studies name no path of the machine they were made on.

A path like /work/runs/x or /home/me/granshock in docs/results says nothing to a reader on
another machine: results, scripts and tables name paths relative to the repository.
Flagged, in every text file under docs/, scenes/ and studies/ and in README.md:
  - an absolute path under a home or work tree: /work, /home, /Users, /root, /scratch,
    /mnt, /media, /data (the start of a path, not part of a URL or a longer path);
  - under docs/results/ also /tmp and /var/tmp: a result's files were there on one
    machine (a documented command may write to /tmp elsewhere).
Paths of the system (/usr/bin/python3, /dev/shm, /proc) are what a documented command
runs and are allowed.
Usage: no_machine_paths.py REPOSITORY_ROOT
"""
import pathlib
import re
import sys

HOME_TREES = r"work|home|Users|root|scratch|mnt|media|data"
TEMPORARY = r"tmp|var/tmp"
# Not after a character that makes it part of a URL, a longer path or a word.
START = r"(?<![\w.:/~$-])"


def pattern(trees):
    return re.compile(START + r"/(?:" + trees + r")(?=/|\b)")


ANYWHERE = pattern(HOME_TREES)
IN_RESULTS = pattern(HOME_TREES + "|" + TEMPORARY)


def text_files(root):
    for top in ("docs", "scenes", "studies"):
        for path in sorted((root / top).rglob("*")):
            if path.is_file():
                yield path
    yield root / "README.md"


def main():
    root = pathlib.Path(sys.argv[1]).resolve()
    found = []
    for path in text_files(root):
        data = path.read_bytes()
        if b"\0" in data[:8192]:
            continue  # a figure, an HDF5 file
        relative = path.relative_to(root).as_posix()
        check = IN_RESULTS if relative.startswith("docs/results/") else ANYWHERE
        for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            for match in check.finditer(line):
                found.append(f"{relative}:{number}: {line.strip()[:120]}")
                break
    for line in found:
        print("machine path:", line)
    print(f"{len(found)} line(s) with a machine path")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())

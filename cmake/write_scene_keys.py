#!/usr/bin/python3
"""Writes the table of `granshock keys` into docs/scene_keys.md's "Keys" section, in
place of the table there (the test SceneSchema.TheDocsTableIsTheOneTheSchemaMakes compares
them). Run by `cmake --build build --target scene_keys_doc`.

Usage: write_scene_keys.py GRANSHOCK DOC"""
import os
import subprocess
import sys


def main(granshock, doc):
    table = subprocess.run([granshock, "keys"], check=True, capture_output=True,
                           text=True).stdout
    lines = open(doc, encoding="utf-8").read().split("\n")
    start = lines.index("## Keys")
    first = next(i for i in range(start, len(lines)) if lines[i].startswith("|"))
    last = first
    while last < len(lines) and lines[last].startswith("|"):
        last += 1
    lines[first:last] = table.rstrip("\n").split("\n")
    with open(doc + ".new", "w", encoding="utf-8") as out:
        out.write("\n".join(lines))
    os.replace(doc + ".new", doc)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])

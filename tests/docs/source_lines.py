"""The lines of the repository's source files, for the checks of tests/docs/."""
import pathlib


def source_lines(root, layers, suffixes, names=(), skip=None):
    """Yields (path relative to root, line number, line) for every file under the given
    layers whose suffix is in `suffixes` or whose name is in `names`, `skip` excepted."""
    for layer in layers:
        for path in sorted((root / layer).rglob("*")):
            if path.suffix not in suffixes and path.name not in names:
                continue
            if not path.is_file() or (skip is not None and path.resolve() == skip):
                continue
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                yield path.relative_to(root), number, line


def report(found, problem, fine):
    """Prints the offending lines and a verdict; the exit status."""
    for line in found:
        print(line)
    if found:
        print(f"{len(found)} {problem}")
        return 1
    print(fine)
    return 0

"""What kind of granshock directory a path is (docs/output_format.md, "The run directory",
"The fields directory"; docs/study.md, "The study directory")."""
import pathlib

from .errors import GranshockError

RUN_MARKER = ".granshock-run"
FIELDS_MARKER = ".granshock-fields"
STUDY_MARKER = ".granshock-study"


def existing_directory(path):
    """The path as a pathlib.Path, or a GranshockError when it is no directory."""
    path = pathlib.Path(path)
    if not path.exists():
        raise GranshockError(path, "no such directory")
    if not path.is_dir():
        raise GranshockError(path, "is not a directory (give the directory that holds "
                             "granshock's files)")
    return path


def read_marker(path):
    """The `key = value` lines of a marker file as a dict (its first line, a sentence for
    the user, is skipped); {} for an empty marker, which granshock counts as its own."""
    lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    pairs = (line.split("=", 1) for line in lines[1:] if "=" in line)
    return {key.strip(): value.strip() for key, value in pairs}


def run_or_fields_kind(path):
    """'run' for a directory with run.h5, 'fields' for one with fields.h5 but no run.h5
    (`granshock fields RUN --out DIR`); otherwise a GranshockError saying what it is.

    The HDF5 files decide, not the marker: a copy made with `cp DIR/*` has no dot files.
    """
    path = existing_directory(path)
    if (path / "run.h5").exists():
        return "run"
    if (path / "fields.h5").exists():
        return "fields"
    if (path / STUDY_MARKER).exists():
        raise GranshockError(path, "is a study directory: open it with open_study(), "
                             "its cases with Study.run(case)")
    if (path / FIELDS_MARKER).exists() and (path / "detachment.csv").exists():
        raise GranshockError(path, "holds the comparison of several runs (detachment.csv, "
                             "detachment.json), not one run's fields: read those with pandas")
    if (path / RUN_MARKER).exists():
        raise GranshockError(path, "is a run directory without run.h5: the run stopped "
                             "before writing it")
    raise GranshockError(path, "is not a granshock run or fields directory "
                         "(it holds neither run.h5 nor fields.h5)")

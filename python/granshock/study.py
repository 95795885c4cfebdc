"""A study directory (`granshock study`, docs/study.md, "The study directory"): one run
directory per case, and the study table in study.json and study.csv."""
import functools
import json

import pandas as pd

from .directory import STUDY_MARKER, existing_directory, read_marker
from .errors import GranshockError
from .run import open_run


def open_study(directory):
    """Opens a study directory; returns a Study.

    Raises GranshockError (a ValueError) naming the path when it does not exist or carries
    neither the study's marker nor its table.
    """
    return Study(directory)


class Study:
    """A study: `name`, the `table` (one row per case), the `cases` and each case's run."""

    def __init__(self, directory):
        self.path = existing_directory(directory)
        marker = self.path / STUDY_MARKER
        if not marker.exists() and not (self.path / "study.json").exists():
            raise GranshockError(self.path, f"is not a granshock study directory (it has "
                                 f"neither {STUDY_MARKER} nor study.json)")
        self.name = read_marker(marker).get("study") if marker.exists() else None

    def __repr__(self):
        return f"<granshock.Study {self.name!r} in {str(self.path)!r}>"

    @functools.cached_property
    def table(self):
        """The study table as a pandas DataFrame, one row per case in case order (columns:
        case, index, status, wall_seconds, axis.*, scene.*, error, then every scalar of the
        finished cases' summary.json; docs/study.md, "The study table"). Read from
        study.json, which keeps full precision, text and booleans; NaN/None where a value
        is undeterminable or the case not finished."""
        path = self.path / "study.json"
        if not path.is_file():
            raise GranshockError(path, "no such file: the table is written once the cases "
                                 "have run (granshock study STUDY.toml --collect writes it)")
        try:
            rows = json.loads(path.read_text(encoding="utf-8"))
        except (ValueError, UnicodeDecodeError) as e:
            raise GranshockError(path, f"is not JSON ({e})") from e
        return pd.DataFrame(rows)

    @property
    def cases(self):
        """The case names, in case order (the table's `case` column)."""
        return list(self.table["case"])

    def run(self, case):
        """The run of one case (its name, or its --case number) as a Run. A case that has
        not run yet raises GranshockError; a case not in the table, KeyError."""
        if isinstance(case, int):
            if not 0 <= case < len(self.cases):
                raise KeyError(f"case {case}: the study has cases 0 to {len(self.cases) - 1}")
            case = self.cases[case]
        elif (self.path / "study.json").is_file() and case not in self.cases:
            # Without the table (array tasks still running) any case directory opens.
            raise KeyError(f"case {case!r} is not one of the study's: {', '.join(self.cases)}")
        directory = self.path / case
        if not directory.exists():
            raise GranshockError(directory, f"case {case!r} has not run yet (no directory)")
        return open_run(directory)

    def runs(self):
        """{case name: Run} of the finished cases."""
        finished = self.table.loc[self.table["status"] == "finished", "case"]
        return {case: self.run(case) for case in finished}

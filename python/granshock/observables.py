"""The time series of run.h5 (docs/output_format.md, "Time series (/observables)"): one
H5MD group per column, each with `step`, `time` and `value` of the same length."""
import numpy as np
import pandas as pd

from ._h5 import in_order, text
from .errors import GranshockError

OBSERVABLES = "observables"
# Its step marks a row as complete: written last of a row (io/run_file_series.cpp).
ROW_MARKER = "particles"
# The columns in the order docs/output_format.md lists them.
COLUMN_ORDER = ["particles", "kinetic_energy", "temperature", "contacts", "inserted",
                "deleted_outlet", "deleted_inlet"]


def read_observables(f):
    """Every /observables/NAME series of an open run.h5 as one DataFrame indexed by step,
    with a `time` column (s) first; units (where the file names one) in `.attrs["units"]`.
    Only complete rows: a crash can leave the other series one entry longer."""
    group = f.get(OBSERVABLES)
    if group is None or ROW_MARKER not in group:
        return pd.DataFrame({"time": []}, index=pd.Index([], name="step", dtype="int64"))
    rows = len(group[ROW_MARKER]["step"])
    steps = pd.Index(group[ROW_MARKER]["step"][()], name="step")
    frame = pd.DataFrame({"time": group[ROW_MARKER]["time"][()]}, index=steps)
    units = {"time": "s"}
    for name in in_order(group, COLUMN_ORDER):
        series = group[name]
        if not np.array_equal(series["step"][:rows], steps):
            raise GranshockError(f.filename, f"/observables/{name}: its steps differ from "
                                 f"/observables/{ROW_MARKER}'s")
        frame[name] = series["value"][:rows]
        if "unit" in series["value"].attrs:
            units[name] = text(series["value"].attrs["unit"])
    frame.attrs["units"] = units
    return frame

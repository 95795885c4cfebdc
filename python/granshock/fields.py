"""The averaged fields of fields.h5 (docs/fields.md, section 8, "fields.h5"): every
/fields/NAME is [ny, nx] on the bin grid, row j at y[j], column i at x[i]."""
from collections.abc import Mapping

import numpy as np
import pandas as pd

from ._h5 import attributes, text


class Fields(Mapping):
    """A read-only mapping of field name (phi, T, Ma, ux, ..., masked; docs/fields.md) to
    its [ny, nx] numpy array, with the grid: `x`, `y` (bin centres, m), `x_nodes`,
    `y_nodes` (bin edges, m), `grid` (nx, ny, x0, y0, dx, dy), and each field's `units`
    and `descriptions`."""

    def __init__(self, arrays, grid, x, y, x_nodes, y_nodes, units, descriptions):
        self._arrays = arrays
        self.grid, self.x, self.y = grid, x, y
        self.x_nodes, self.y_nodes = x_nodes, y_nodes
        self.units, self.descriptions = units, descriptions

    def __getitem__(self, name):
        return self._arrays[name]

    def __iter__(self):
        return iter(self._arrays)

    def __len__(self):
        return len(self._arrays)

    def __repr__(self):
        return f"<Fields on {len(self.y)} x {len(self.x)} bins: {', '.join(self)}>"

    def to_dataframe(self):
        """One row per bin: its centre x, y and every field (a long table for pandas)."""
        x, y = np.meshgrid(self.x, self.y)
        columns = {"x": x.ravel(), "y": y.ravel()}
        columns.update((name, values.ravel()) for name, values in self._arrays.items())
        return pd.DataFrame(columns)


def read_fields(f):
    """The fields of an open fields.h5."""
    arrays, units, descriptions = {}, {}, {}
    for name, dataset in f["fields"].items():
        arrays[name] = dataset[()]
        if "unit" in dataset.attrs:
            units[name] = text(dataset.attrs["unit"])
        if "description" in dataset.attrs:
            descriptions[name] = text(dataset.attrs["description"])
    grid = f["grid"]
    return Fields(arrays, attributes(grid), grid["x"][()], grid["y"][()],
                  grid["x_nodes"][()], grid["y_nodes"][()], units, descriptions)

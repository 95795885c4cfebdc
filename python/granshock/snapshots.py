"""Particle snapshots of run.h5 (docs/output_format.md, "Particle snapshots"): each
element's `value` is padded past the frame's count with NaN or -1, and rows are in the
solver's order, which changes between frames; a snapshot here is trimmed and sorted by id."""
from collections.abc import Mapping

import h5py
import numpy as np
import pandas as pd

from ._h5 import in_order

PARTICLES = "particles/all"
# Groups under /particles/all that are not per-particle elements.
NOT_ELEMENTS = {"box", "count"}
# The order of a snapshot's elements.
ELEMENT_ORDER = ["position", "velocity", "angular_velocity", "species", "radius", "id"]


def frame_steps_and_times(f):
    """(steps, times) of the complete snapshots: the `count` series, written last of a
    snapshot, so that a frame cut short by a crash is not counted."""
    count = f.get(PARTICLES + "/count")
    if count is None:
        return np.zeros(0, dtype=np.int64), np.zeros(0)
    return count["step"][()], count["time"][()]


def element_names(f):
    """The per-particle elements the file holds (position, velocity, species, id and, by
    format and scene, radius and angular_velocity), in ELEMENT_ORDER."""
    group = f[PARTICLES]
    names = [name for name in group
             if name not in NOT_ELEMENTS and isinstance(group[name], h5py.Group)
             and "value" in group[name]]
    return in_order(names, ELEMENT_ORDER)


class Snapshot(Mapping):
    """One snapshot: a read-only mapping of element name (position, velocity, species, id,
    radius, angular_velocity where present) to its array, one row per particle, the rows
    sorted by id. Also `index`, `step`, `time` (s) and `count` (particles)."""

    def __init__(self, index, step, time, elements):
        self.index, self.step, self.time = index, step, time
        self._elements = elements
        self.count = len(elements["id"])

    def __getitem__(self, name):
        return self._elements[name]

    def __iter__(self):
        return iter(self._elements)

    def __len__(self):
        return len(self._elements)

    def __repr__(self):
        return (f"<Snapshot {self.index}: step {self.step}, t = {self.time} s, "
                f"{self.count} particles, {', '.join(self)}>")

    def to_dataframe(self):
        """The snapshot as a pandas DataFrame indexed by id: one column per scalar element,
        and x, y (z) and vx, vy (vz) for position and velocity."""
        columns = {}
        for name, values in self._elements.items():
            if name == "id":
                continue
            if values.ndim == 1:
                columns[name] = values
                continue
            prefix = {"position": "", "velocity": "v"}.get(name, name + "_")
            for axis in range(values.shape[1]):
                columns[prefix + "xyz"[axis]] = values[:, axis]
        return pd.DataFrame(columns, index=pd.Index(self._elements["id"], name="id"))


def read_snapshot(f, index):
    """Snapshot `index` (negative counts from the end) of an open run.h5."""
    steps, times = frame_steps_and_times(f)
    frames = len(steps)
    if not -frames <= index < frames:
        raise IndexError(f"snapshot {index} out of range: run.h5 holds {frames}")
    index %= frames
    count = int(f[PARTICLES + "/count/value"][index])
    elements = {name: f[f"{PARTICLES}/{name}/value"][index, :count]
                for name in element_names(f)}
    order = np.argsort(elements["id"], kind="stable")
    return Snapshot(index, int(steps[index]), float(times[index]),
                    {name: values[order] for name, values in elements.items()})

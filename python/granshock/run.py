"""A run directory (`granshock run`) or a fields directory (`granshock fields RUN --out
DIR`), read lazily: each property reads its file when first asked for and keeps it."""
import functools
import json
import pathlib
import tomllib

from . import _h5
from .directory import run_or_fields_kind
from .errors import GranshockError, NoRunFileError
from .fields import read_fields
from .fronts import read_fronts
from .obstacle import obstacle_from_fields_attributes, obstacle_from_scene
from .observables import read_observables
from .snapshots import frame_steps_and_times, read_snapshot


def open_run(directory):
    """Opens a run directory or a fields directory; returns a Run.

    Raises GranshockError (a ValueError) naming the path when it does not exist, is not a
    directory, or holds neither a granshock run.h5 nor a granshock fields.h5.
    """
    return Run(directory)


class Run:
    """The outputs of one run (or of one run's field analysis).

    kind: "run" (run.h5 is there) or "fields" (a fields directory: fields.h5 and
    summary.json only; also a study case's record, docs/study.md "Campaign records", whose
    reduced fields.h5 holds fewer fields, as float32, and whose scene.toml gives scene). In a fields directory scene, observables, times, steps and
    snapshot() raise NoRunFileError; everything else works in both.
    """

    def __init__(self, directory):
        self.path = pathlib.Path(directory)
        self.kind = run_or_fields_kind(self.path)
        # Refuse a foreign or damaged file now rather than at the first property.
        with self._open(self.kind):
            pass

    def __repr__(self):
        return f"<granshock.Run {str(self.path)!r} ({self.kind} directory)>"

    def _open(self, kind):
        if kind == "run" and self.kind != "run":
            raise NoRunFileError(self.path, "is a fields directory (granshock fields RUN "
                                 "--out DIR): it has no run.h5; open the run directory for "
                                 "the scene, the time series and the snapshots")
        return _h5.open_file(self.path / f"{kind}.h5", kind)

    @functools.cached_property
    def summary(self):
        """summary.json as a dict (null values are None)."""
        path = self.path / "summary.json"
        if not path.is_file():
            raise GranshockError(path, "no such file (a run writes it when it ends)")
        try:
            return json.loads(path.read_text(encoding="utf-8"))
        except (ValueError, UnicodeDecodeError) as e:
            raise GranshockError(path, f"is not JSON ({e})") from e

    @functools.cached_property
    def scene(self):
        """The resolved scene (every default filled in, lengths in m) as a dict, parsed from
        run.h5's /scene/resolved, or in a case's record (docs/study.md, "Campaign records")
        from its scene.toml."""
        record_scene = self.path / "scene.toml"
        if self.kind == "fields" and record_scene.is_file():
            with open(record_scene, "rb") as f:
                return tomllib.load(f)
        with self._open("run") as f:
            return tomllib.loads(_h5.read_text(f["scene/resolved"]))

    @functools.cached_property
    def observables(self):
        """The time series as a pandas DataFrame indexed by step: a `time` column (s) and
        one column per /observables series (particles, kinetic_energy, temperature,
        contacts, inserted, deleted_outlet, deleted_inlet); units in `.attrs["units"]`."""
        with self._open("run") as f:
            return read_observables(f)

    @functools.cached_property
    def thermo(self):
        """thermo.txt, the run's thermo table (docs/output_format.md), as a pandas DataFrame:
        one row per progress report of every leg (Step, Time, Particles, Contacts, KinEng,
        Temp, Inserted, Deleted, PartSteps/s, Done, ETA)."""
        import pandas

        path = self.path / "thermo.txt"
        if not path.is_file():
            raise NoRunFileError(path, "no such file (a run writes it as it goes)")
        return pandas.read_csv(path, sep=r"\s+", comment="#")

    @functools.cached_property
    def times(self):
        """The snapshot times (s), a numpy array; snapshot(i) is the one at times[i]."""
        with self._open("run") as f:
            return frame_steps_and_times(f)[1]

    @functools.cached_property
    def steps(self):
        """The snapshot steps, a numpy array."""
        with self._open("run") as f:
            return frame_steps_and_times(f)[0]

    def snapshot(self, index):
        """Snapshot `index` (0-based; negative counts from the end) as a Snapshot: a mapping
        of element name (position, velocity, species, id, radius, angular_velocity where
        present) to arrays trimmed to the frame's count and sorted by id."""
        with self._open("run") as f:
            return read_snapshot(f, index)

    @functools.cached_property
    def species(self):
        """The species names, in the order of their index in snapshot()["species"]: the
        scene's in a run directory; in a fields directory fields.h5's @species, spelt as
        the per-species fields are (characters other than letters, digits, _ and - as _)."""
        if self.kind == "run":
            return [s["name"] for s in self.scene["species"]]
        return self._fields_attributes["species"].split(",")

    @functools.cached_property
    def _fields_attributes(self):
        with self._open("fields") as f:
            return _h5.attributes(f)

    def _read_fields_file(self, reader):
        if not (self.path / "fields.h5").exists():
            raise GranshockError(self.path / "fields.h5", "no such file (the field analysis "
                                 "has not run: granshock fields DIR writes it)")
        with self._open("fields") as f:
            return reader(f)

    @functools.cached_property
    def fields(self):
        """The averaged fields of fields.h5 as a Fields mapping (name -> [ny, nx] array,
        with the bin centres x, y)."""
        return self._read_fields_file(read_fields)

    @functools.cached_property
    def fronts(self):
        """The shock fronts and detachment lengths of fields.h5, as a Fronts."""
        return self._read_fields_file(read_fronts)

    @functools.cached_property
    def obstacle(self):
        """The obstacle as an Obstacle (shape, centre, sizes, outline), None when the scene
        has none: from the resolved scene in a run directory, from fields.h5's attributes in
        a fields directory."""
        if self.kind == "run":
            return obstacle_from_scene(self.scene)
        with self._open("fields") as f:
            outline = f["obstacle/outline"][...] if "obstacle/outline" in f else None
        return obstacle_from_fields_attributes(self._fields_attributes, outline)

"""granshock's outputs in Python: run and fields directories, and studies.

    import granshock
    run = granshock.open_run("runs/default")
    print(run.summary["delta_over_D"], run.fronts.definitions)

docs/python.md describes every function; docs/output_format.md and docs/fields.md the
files. Needs h5py, numpy and pandas (Debian: python3-h5py python3-pandas).
"""
from .errors import GranshockError, NoRunFileError
from .fields import Fields
from .fronts import Fronts
from .obstacle import Obstacle, obstacle_from_scene
from .run import Run, open_run
from .snapshots import Snapshot
from .study import Study, open_study

__all__ = ["open_run", "open_study", "Run", "Study", "Snapshot", "Fields", "Fronts",
           "Obstacle", "obstacle_from_scene", "GranshockError", "NoRunFileError"]

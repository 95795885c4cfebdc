"""The exceptions of the reader: one class for every file problem, naming the path."""


class GranshockError(ValueError):
    """A path that is missing, unreadable, or not what granshock writes there.

    The message names the path; `path` holds it too.
    """

    def __init__(self, path, problem):
        self.path = str(path)
        super().__init__(f"{path}: {problem}")


class NoRunFileError(GranshockError):
    """What only run.h5 holds (scene, observables, snapshots) was asked of a directory
    without one: a fields directory (`granshock fields RUN --out DIR`)."""

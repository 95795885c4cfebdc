"""HDF5 helpers: opening granshock's files with clear errors, and attributes as Python
values (docs/output_format.md: strings are fixed-length NUL-terminated bytes)."""
import contextlib

import h5py
import numpy as np

from .errors import GranshockError

# The newest format of each file this reader knows (the files' @granshock_format_version).
KNOWN_FORMATS = {"run": 3, "fields": 2}


def text(value):
    """A stored string as str: h5py gives fixed-length strings as bytes."""
    if isinstance(value, (bytes, np.bytes_)):
        return bytes(value).rstrip(b"\0").decode("utf-8")
    return str(value)


def python_value(value):
    """An attribute as a plain Python value: str, int, float, or a numpy array."""
    if isinstance(value, (bytes, np.bytes_, str)):
        return text(value)
    if isinstance(value, np.ndarray) and value.ndim > 0:
        return value
    return value.item() if isinstance(value, (np.generic, np.ndarray)) else value


def attributes(obj):
    """Every attribute of an HDF5 object, as {name: python_value}."""
    return {name: python_value(obj.attrs[name]) for name in obj.attrs}


def in_order(names, order):
    """`names` sorted as they appear in `order`, the others last in their own order: HDF5
    lists groups and attributes alphabetically, the docs in an order that reads better."""
    return sorted(names, key=lambda n: order.index(n) if n in order else len(order))


def read_text(dataset):
    """A scalar string dataset (such as /scene/resolved) as str."""
    return text(dataset[()])


@contextlib.contextmanager
def open_file(path, kind):
    """Opens run.h5 or fields.h5 for reading, checking that granshock wrote it as `kind`
    ("run" or "fields") in a format this reader knows; every failure is a GranshockError."""
    if not path.is_file():
        raise GranshockError(path, "no such file")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        if "lock" in str(e):
            # HDF5 locks a file while granshock writes it (docs/output_format.md, run.h5).
            raise GranshockError(path, "is open for writing (a run in progress?); "
                                 "HDF5_USE_FILE_LOCKING=FALSE in the environment reads "
                                 "its last flushed state") from e
        raise GranshockError(path, f"is not an HDF5 file granshock wrote ({e})") from e
    with f:
        found = text(f.attrs.get("granshock_file", b""))
        if found != kind:
            what = f"a granshock {found} file" if found else "no granshock file"
            raise GranshockError(path, f"is {what}, not a {kind} file (@granshock_file)")
        version = int(f.attrs.get("granshock_format_version", 1))
        if version > KNOWN_FORMATS[kind]:
            raise GranshockError(path, f"is a {kind} file of format {version}, newer than this "
                                 f"reader knows (up to {KNOWN_FORMATS[kind]})")
        try:
            yield f
        except OSError as e:
            # A stored Fletcher32 checksum that does not match, a truncated file.
            raise GranshockError(path, f"is damaged: reading it failed ({e})") from e

"""Atomic output files: written into a temporary file beside the target and renamed into
place, so that a reader (or a killed run) never sees half a file. The file gets the
permissions of a plain ``open()`` (0666 less the umask), not mkstemp's 0600.
Standard library only (the runtime writes its outputs through it).
"""
from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


@contextlib.contextmanager
def atomic_output(path, mode: str = "wb", directory=None):
    """Yield a file object open on a temporary file; on a clean exit it replaces ``path``
    (os.replace), on an exception it is removed and ``path`` is left as it was.
    directory: where the temporary file lives (default: path's directory; it must be on the
    same file system)."""
    path = Path(path)
    where = Path(directory) if directory is not None else (path.parent if str(path.parent)
                                                            else Path("."))
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=where)
    try:
        with os.fdopen(fd, mode) as fh:
            yield fh
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def write_file(path, data: bytes | str) -> None:
    """Write ``data`` (str as UTF-8) to ``path`` atomically."""
    with atomic_output(path) as fh:
        fh.write(data.encode() if isinstance(data, str) else data)

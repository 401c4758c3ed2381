"""Build cache: one directory per key, key = sha256 of everything that changes the code.

Layout: <cache_dir>/<key>/<module files> + MANIFEST.json (sha256 of every source file).
Entries are written into a temporary directory and renamed into place (atomic); a lock
file per key (fcntl.flock) makes concurrent compiles of the same input share one entry.
A corrupted entry (a file missing or changed) is detected and rebuilt.
Standard library only: a cache hit must not import the compile-time stack.
"""
from __future__ import annotations

import contextlib
import fcntl
import hashlib
import json
import os
import shutil
import tempfile
from pathlib import Path

MANIFEST = "MANIFEST.json"


def default_cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "hpgen"


def cache_key(*parts: str) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode())
        h.update(b"\0")
    return h.hexdigest()


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def is_valid(entry: Path) -> bool:
    """True when the entry exists and every file listed in its manifest is intact."""
    try:
        manifest = json.loads((entry / MANIFEST).read_text())
        return all(_digest(entry / name) == digest for name, digest in manifest["files"].items())
    except (OSError, ValueError, KeyError, TypeError):
        return False


@contextlib.contextmanager
def locked(cache_dir: Path, key: str):
    cache_dir.mkdir(parents=True, exist_ok=True)
    with open(cache_dir / f"{key}.lock", "w") as fh:
        fcntl.flock(fh, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def write_tree(dest: Path, files: dict[str, bytes | str], manifest: bool = True) -> Path:
    """Write files into ``dest`` atomically: a temp dir beside it, renamed into place.

    An existing ``dest`` is replaced as a whole (moved aside, then removed).
    """
    dest = Path(dest)
    dest.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{dest.name}.tmp-", dir=dest.parent))
    try:
        digests = {}
        for name, data in sorted(files.items()):
            p = tmp / name
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_bytes(data.encode() if isinstance(data, str) else data)
            digests[name] = _digest(p)
        if manifest:
            (tmp / MANIFEST).write_text(json.dumps({"files": digests}, indent=1, sort_keys=True) + "\n")
        old = None
        if dest.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{dest.name}.old-", dir=dest.parent))
            os.replace(dest, old / "x")
        os.replace(tmp, dest)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return dest


def read_tree(entry: Path) -> dict[str, bytes]:
    """The files of a cache entry (those in its manifest), by relative name."""
    manifest = json.loads((entry / MANIFEST).read_text())
    return {name: (entry / name).read_bytes() for name in manifest["files"]}

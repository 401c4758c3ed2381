"""Build cache: content-addressed directories, written atomically, checked before use.

Layout (see hpgen.api for the keys):
  <cache_dir>/<derivation key>/   a generated module's files + MANIFEST.json (their sha256)
                                  + links to its built libraries (hpgen.runtime.build)
  <cache_dir>/lib/                the C libraries, named by the hash of kernels.c, compiler
                                  and flags, each with a record of its own sha256
Entries are written into a temporary directory and renamed into place (atomic); a lock
file per key (fcntl.flock) makes concurrent compiles of the same input share one entry.
A corrupted entry (a file missing or changed) is detected and rebuilt; a file added to a valid
entry later (the other backend's source, ``add_files``) counts once its manifest lists it. A module directory
with a MANIFEST.json (a cache entry, ``hpgen compile -o`` output) is checked against it
before it is built or loaded (``check_sources``). A cache directory that cannot be written
raises CacheUnwritable; the caller then builds in a private temporary directory.
Standard library only: a cache hit must not import the compile-time stack.
"""
from __future__ import annotations

import atexit
import contextlib
import fcntl
import hashlib
import json
import os
import shutil
import tempfile
from pathlib import Path

from .errors import BuildError, ModelError

MANIFEST = "MANIFEST.json"
LIBRARY_STORE = "lib"


class CacheUnwritable(BuildError):
    """A cache (or module) directory cannot be written (read-only, not a directory, full)."""

    def __init__(self, directory, exc: OSError):
        self.directory = Path(directory)
        self.reason = exc.strerror or str(exc)
        super().__init__(f"cannot write in {directory} ({self.reason})")


def default_cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "hpgen"


def library_store(cache_dir) -> Path:
    """The directory of the built libraries shared by a cache's entries."""
    return Path(cache_dir) / LIBRARY_STORE


def private_cache_dir() -> Path:
    """A fresh temporary cache directory for this process, removed when it exits."""
    path = Path(tempfile.mkdtemp(prefix="hpgen-cache-"))
    atexit.register(shutil.rmtree, path, True)
    return path


def cache_key(*parts: str) -> str:
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode())
        h.update(b"\0")
    return h.hexdigest()


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _bad_files(module_dir: Path) -> list[str] | None:
    """The files listed in ``module_dir``'s manifest that are missing or changed ([MANIFEST]
    when the manifest is unreadable); None when there is no manifest."""
    path = Path(module_dir) / MANIFEST
    if not path.exists():
        return None
    try:
        files = json.loads(path.read_text())["files"]
        return sorted(name for name, digest in files.items()
                      if not _matches(Path(module_dir) / name, digest))
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return [MANIFEST]


def is_valid(entry: Path) -> bool:
    """True when the entry exists and every file listed in its manifest is intact."""
    return _bad_files(entry) == []


def has_files(entry: Path, names) -> bool:
    """True when the entry is valid (is_valid) and its manifest lists every one of ``names``
    (a backend's source that a compile for the other backend did not write is not listed)."""
    try:
        listed = json.loads((Path(entry) / MANIFEST).read_text())["files"]
    except (OSError, ValueError, KeyError, TypeError):
        return False
    return isinstance(listed, dict) and all(n in listed for n in names) and is_valid(entry)


def add_files(entry: Path, files: dict[str, bytes | str]) -> None:
    """Add ``files`` to a valid entry: each written to a temporary file and renamed into
    place, then the manifest, extended by their digests, replaced the same way. Until the
    manifest lists a file, readers treat it as missing (has_files), so a write cut short
    leaves at most an unlisted file that the next add replaces. The caller holds the entry's
    lock (``locked``)."""
    entry = Path(entry)
    manifest = json.loads((entry / MANIFEST).read_text())
    for name, data in sorted(files.items()):
        _replace(entry / name, data.encode() if isinstance(data, str) else data)
        manifest["files"][name] = _digest(entry / name)
    _replace(entry / MANIFEST, (json.dumps(manifest, indent=1, sort_keys=True) + "\n").encode())


def _replace(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically (a temporary file beside it, renamed)."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.tmp-", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def check_sources(module_dir) -> None:
    """Raise ModelError when ``module_dir`` has a MANIFEST.json and a file it lists is
    missing or differs from its recorded sha256 (e.g. kernels.c edited by hand); a directory
    without a manifest (``generated/``) is not checked."""
    module_dir = Path(module_dir)
    bad = _bad_files(module_dir)
    if bad:
        raise ModelError(f"{', '.join(bad)} differ{'s' if len(bad) == 1 else ''} from the "
                         f"digests recorded in {MANIFEST} (edited by hand?); refusing to build "
                         "or load it: regenerate the module (hpgen compile -o) or compile "
                         "from the cache", file=str(module_dir / bad[0]))


def _matches(path: Path, digest: str) -> bool:
    try:
        return _digest(path) == digest
    except OSError:
        return False


@contextlib.contextmanager
def locked(cache_dir: Path, key: str):
    """An exclusive lock on ``<cache_dir>/<key>.lock``; CacheUnwritable if it cannot be made."""
    cache_dir = Path(cache_dir)
    try:
        cache_dir.mkdir(parents=True, exist_ok=True)
        fh = open(cache_dir / f"{key}.lock", "a")
    except OSError as exc:
        raise CacheUnwritable(cache_dir, exc) from None
    with fh:
        fcntl.flock(fh, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def write_tree(dest: Path, files: dict[str, bytes | str], manifest: bool = True,
               unlisted: dict[str, bytes] | None = None) -> Path:
    """Write files into ``dest`` atomically: a temp dir beside it, renamed into place.

    MANIFEST.json (if ``manifest``) lists ``files``; ``unlisted`` files (built libraries,
    which carry their own records) are written but not listed. An existing ``dest`` is
    replaced as a whole (moved aside, then removed).
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
        for name, data in (unlisted or {}).items():
            (tmp / name).write_bytes(data)
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

"""Shipping a generated module to Dask workers: its source files and their content hash.

Workers need hpgen and a C compiler, no shared file system: the client sends the module's
source files the C backend reads (meta.json and kernels.c, never a built library) with
``digest``, the sha256 of their names and bytes, once per worker (scattered, broadcast). A
worker checks the digest of what it received, writes the files into its own build cache
(``<cache>/sweep/<digest>/``, atomic, with a manifest of their sha256; hpgen.runtime.build
checks the sources against it before building or loading), builds the C library there once
(locked against concurrent builders) and keeps the loaded Integrator for the life of its
process. An entry already in the cache is used
only when its files still match the manifest and the digest; otherwise it is rewritten.
Standard library and numpy (hpgen.runtime) only: no compile-time stack on the workers.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from .. import cache
from ..errors import BuildError, ModelError

#: the cache subdirectory of modules installed from a payload
SUBDIR = "sweep"
#: the files of a module directory that the C backend reads
SHIPPED = ("meta.json", "kernels.c")


@dataclass(frozen=True)
class ModulePayload:
    """A generated module's source files {name: bytes} and their ``digest``."""
    digest: str
    files: tuple          # ((name, bytes), ...) sorted by name


def files_digest(files) -> str:
    """sha256 over the sorted (name, bytes) pairs."""
    h = hashlib.sha256()
    for name, data in sorted(files):
        h.update(name.encode() + b"\0" + len(data).to_bytes(8, "little") + data)
    return h.hexdigest()


def payload_of(integ) -> ModulePayload:
    """The payload of a loaded Integrator (its module directory's source files)."""
    module_dir = getattr(integ, "module_dir", None)
    if module_dir is None:
        raise ModelError("the integrator was not loaded from a module directory (use "
                         "hpgen.compile or hpgen.load)", field="integ")
    try:
        files = tuple((name, (Path(module_dir) / name).read_bytes()) for name in SHIPPED)
    except OSError as exc:
        raise BuildError(f"cannot read the module to ship to the workers: {exc}") from None
    return ModulePayload(files_digest(files), files)


def install(payload: ModulePayload, cache_dir=None) -> Path:
    """The module directory of ``payload`` in this machine's cache, written if missing or
    damaged; BuildError when the received files do not match the digest."""
    if files_digest(payload.files) != payload.digest:
        raise BuildError(f"the module files received do not match their content hash "
                         f"{payload.digest[:16]} (damaged in transit)")
    root = Path(cache_dir) if cache_dir else cache.default_cache_dir()
    entry = root / SUBDIR / payload.digest
    if _intact(entry, payload):
        return entry
    with cache.locked(root / SUBDIR, payload.digest):
        if not _intact(entry, payload):
            cache.write_tree(entry, dict(payload.files))
    return entry


def _intact(entry: Path, payload: ModulePayload) -> bool:
    if not cache.is_valid(entry):
        return False
    try:
        return files_digest((n, (entry / n).read_bytes()) for n, _ in payload.files) \
            == payload.digest
    except OSError:
        return False


#: Integrators loaded in this process, by digest (a worker loads a module once)
_LOADED: dict = {}


def integrator(payload: ModulePayload, cache_dir=None):
    """The loaded (C backend) Integrator of ``payload`` in this process."""
    integ = _LOADED.get(payload.digest)
    if integ is None:
        from ..runtime import load
        integ = _LOADED[payload.digest] = load(install(payload, cache_dir), backend="c")
    return integ


def run_task(payload: ModulePayload, m, start, steps, every, record, threads, cache_dir=None):
    """A Dask task: one chunk (hpgen.ensemble.chunk.run_chunk) on this worker."""
    from .chunk import run_chunk
    return run_chunk(integrator(payload, cache_dir), m, start, steps, every, record, threads)

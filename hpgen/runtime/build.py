"""Compile a generated module's kernels.c into a shared library next to it (C backend).

The library is ``_kernels_<hash[:16]>.so`` in the module directory (with a suffix naming the
extra flags when ``cflags`` is given, so differently built libraries never mix). Building is
race-free: an exclusive ``fcntl.flock`` on ``_kernels.lock`` serialises builders, the compiler
writes a temp file in the same directory and ``os.replace`` moves it in place atomically.
Standard library only.
"""
from __future__ import annotations

import fcntl
import hashlib
import json
import os
import shlex
import subprocess
import tempfile
from pathlib import Path

from ..errors import BuildError

#: default flags: portable and reproducible (no -march=native); pass extras via ``cflags``
DEFAULT_CFLAGS = ("-std=c99", "-O3", "-fPIC", "-shared")
#: link inputs placed after the source file
LIBS = ("-lm",)
_TIMEOUT = 600


def library_name(content_hash: str, cflags=None) -> str:
    if not cflags:
        return f"_kernels_{content_hash[:16]}.so"
    tag = hashlib.sha256("\0".join(cflags).encode()).hexdigest()[:8]
    return f"_kernels_{content_hash[:16]}-{tag}.so"


def compiler_command(cc=None) -> list[str]:
    """The compiler as an argv prefix: ``cc`` if given, else $CC, else ``cc``."""
    cc = cc if cc is not None else os.environ.get("CC", "cc")
    argv = shlex.split(cc) if isinstance(cc, str) else list(cc)
    if not argv:
        raise BuildError("no C compiler given (CC is empty)")
    return argv


def build_library(module_dir, cc=None, cflags=None) -> Path:
    """Path of the module's compiled kernels, compiling ``kernels.c`` first if missing.

    cc: compiler command (default $CC or ``cc``); cflags: extra flags appended to
    DEFAULT_CFLAGS (a later -O wins). Raises BuildError (command and stderr) when the compiler
    is missing or fails, or the directory is not writable.
    """
    module_dir = Path(module_dir)
    meta = json.loads((module_dir / "meta.json").read_text())
    extra = tuple(cflags or ())
    target = module_dir / library_name(str(meta["hash"]), extra)
    if target.exists():
        return target
    source = module_dir / "kernels.c"
    if not source.exists():
        raise BuildError(f"{source} is missing")
    argv = compiler_command(cc)
    try:
        lock = open(module_dir / "_kernels.lock", "a")
    except OSError as exc:
        raise BuildError(f"cannot build in {module_dir}: {exc}") from None
    with lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if target.exists():          # another process built it while we waited
            return target
        fd, tmp = tempfile.mkstemp(prefix=".tmp_kernels_", suffix=".so", dir=module_dir)
        os.close(fd)
        cmd = argv + list(DEFAULT_CFLAGS) + list(extra) + ["-o", tmp, str(source)] + list(LIBS)
        try:
            try:
                proc = subprocess.run(cmd, capture_output=True, text=True, timeout=_TIMEOUT)
            except FileNotFoundError:
                raise BuildError("C compiler not found", command=cmd) from None
            except (OSError, subprocess.TimeoutExpired) as exc:
                raise BuildError(f"C compiler could not run ({exc})", command=cmd) from None
            if proc.returncode != 0:
                raise BuildError(f"C compilation failed (exit status {proc.returncode})",
                                 command=cmd, stderr=proc.stderr)
            os.replace(tmp, target)
        finally:
            if os.path.exists(tmp):
                os.unlink(tmp)
    return target

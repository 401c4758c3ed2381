"""Compile a generated module's kernels.c into a shared library (C backend), content-addressed.

kernels.c includes hpgen's static C runtime (the plain C files in RUNTIME_DIR, found by
``-I RUNTIME_DIR``): one translation unit per module (see RUNTIME_LINKING). A kernels.c that
defines HPGEN_PARTS (a family module's, hpgen.codegen.cparts) is compiled as that many
translation units (``-DHPGEN_PART=k -c``, at most one compiler per CPU at a time) whose
objects are linked into the one library.

The library is ``_kernels_<key[:16]>.so`` in the module directory, where ``key`` is the sha256
of kernels.c's bytes, the runtime's sources (``runtime_digest``), the compiler command (with
the path it resolves to) and the flags (``build_key``): the same C built the same way is the
same library, whichever derivation emitted it, and a changed runtime builds a new one.
Beside it, ``_kernels_<key[:16]>.so.json`` records the library's sha256 and its source's. A
library is returned (and so loaded) only when its bytes match that record; one that does not
(truncated, bytes flipped, record missing) is rebuilt, never loaded.

``store`` (the build cache's ``<cache>/lib``) holds the libraries of all cache entries: an
intact one found there is linked (or copied) into the module directory instead of compiled,
so a new derivation that emits the same kernels.c runs no compiler.

Before anything is built or loaded, a module directory holding a MANIFEST.json (cache entries,
``hpgen compile -o`` output) has its sources checked against it (hpgen.cache.check_sources):
a hand-edited kernels.c is refused, never compiled or served from a stale library.

A family module's kernels.c leaves step_partials and hpgen_linearize (the code only
linearize calls, hpgen.codegen.csource.LAZY_KERNELS) out of this step library unless
compiled with LAZY_FLAG: ``build_lazy_library`` builds that second, complete library from the
same kernels.c on first use (the C compiler only), keyed, checked, locked and replaced in the
same way. It holds its own static copies of the runtime and the step's kernels rather than
linking against the step library: no exported internals, no load order, and the run state a
step library initialises is the same struct in both (same kernels.c, same sizes).

Race-free: an exclusive lock per library (hpgen.cache.locked) serialises builders; the compiler
writes a temp file in the same directory and ``os.replace`` moves it in place atomically.
Standard library only.
"""
from __future__ import annotations

import hashlib
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

from ..files import write_file
from .. import cache
from ..errors import BuildError

#: default flags: portable and reproducible (no -march=native); pass extras via ``cflags``
DEFAULT_CFLAGS = ("-std=c99", "-O3", "-fPIC", "-shared")
#: the static C runtime every kernels.c includes (hpgen_runtime.h, hpgen_runtime.c and its
#: parts), shipped in the package
RUNTIME_DIR = Path(__file__).resolve().parent / "c"
#: How the runtime is linked: included into each module's translation unit (kernels.c ends
#: with #include "hpgen_runtime.c"), after the model's sizes (#define HPGEN_NZ ...) and its
#: kernels, rather than compiled once per compiler and flags into an object linked into
#: every module. Included, the sizes are compile-time constants (the LU, the norms and the
#: predictor unroll, work arrays have fixed sizes) and the step's small kernels inline into
#: the Newton loop (HPGEN_FLATTEN); a shared object would call the kernels out of line and
#: loop over runtime sizes. benchmarks/runtime_ab.py --split, portable -O3, medians of 30
#: interleaved rounds: with only the kernels kept out of line (sizes still constant) the
#: Stormer-Verlet heavy-top step takes 1.20x and the free body's lane ensemble 1.08x the
#: included runtime's time (Gauss 2 / 3, whose kernels are too large to inline: 1.00).
RUNTIME_LINKING = "include"
#: link inputs placed after the source file
LIBS = ("-lm",)
_TIMEOUT = 600
#: the flag that builds the lazily built library (kernels.c complete, HPGEN_WITH_LAZY 1)
LAZY_FLAG = "-DHPGEN_LAZY_LIBRARY"
RECORD_SUFFIX = ".json"
_PARTS = re.compile(rb"^#define HPGEN_PARTS ([0-9]+)$", re.M)


def compiler_command(cc=None) -> list[str]:
    """The compiler as an argv prefix: ``cc`` if given, else $CC, else ``cc``."""
    cc = cc if cc is not None else os.environ.get("CC", "cc")
    argv = shlex.split(cc) if isinstance(cc, str) else list(cc)
    if not argv:
        raise BuildError("no C compiler given (CC is empty)")
    return argv


def runtime_sources() -> list[Path]:
    """The runtime's C files (RUNTIME_DIR/*.c, *.h), sorted by name."""
    return sorted(p for p in RUNTIME_DIR.iterdir() if p.suffix in (".c", ".h"))


def runtime_digest() -> str:
    """sha256 over the runtime's C files (names and bytes)."""
    h = hashlib.sha256()
    for p in runtime_sources():
        h.update(p.name.encode() + b"\0" + p.read_bytes() + b"\0")
    return h.hexdigest()


def include_flags() -> list[str]:
    """The compiler flags that let kernels.c find the runtime (``-I RUNTIME_DIR``)."""
    return ["-I", str(RUNTIME_DIR)]


def build_key(source: bytes, argv, cflags=()) -> str:
    """sha256 of the C source, the runtime's sources, the compiler command (and the file it
    resolves to) and flags."""
    return cache.cache_key(hashlib.sha256(source).hexdigest(), runtime_digest(),
                           json.dumps(list(argv)), str(shutil.which(argv[0]) or argv[0]),
                           json.dumps(list(DEFAULT_CFLAGS) + list(cflags) + list(LIBS)))


def library_name(key: str) -> str:
    return f"_kernels_{key[:16]}.so"


def _record_path(lib: Path) -> Path:
    return lib.with_name(lib.name + RECORD_SUFFIX)


def _record(lib: Path) -> dict | None:
    try:
        rec = json.loads(_record_path(lib).read_text())
        return rec if isinstance(rec, dict) else None
    except (OSError, ValueError):
        return None


def intact(lib: Path, source_digest: str) -> bool:
    """True when ``lib`` exists and its bytes and source match its build record."""
    rec = _record(lib)
    try:
        return (rec is not None and rec.get("source_sha256") == source_digest
                and hashlib.sha256(lib.read_bytes()).hexdigest() == rec.get("sha256"))
    except OSError:
        return False


def read_library(lib) -> tuple[bytes, bytes]:
    """(library bytes, record bytes) of a built library, checked against its record (for
    copying a library out); BuildError when they do not match."""
    lib = Path(lib)
    try:
        data, rec = lib.read_bytes(), _record_path(lib).read_bytes()
        ok = hashlib.sha256(data).hexdigest() == json.loads(rec).get("sha256")
    except (OSError, ValueError, AttributeError):
        ok = False
    if not ok:
        raise BuildError(f"{lib} does not match its build record; compile again to rebuild it")
    return data, rec


def _source(module_dir: Path) -> tuple[Path, bytes]:
    cache.check_sources(module_dir)
    source = module_dir / "kernels.c"
    try:
        return source, source.read_bytes()
    except OSError:
        raise BuildError(f"{source} is missing (a module compiled for the Python backend only "
                         "gets it from a compile with backend='c')") from None


def find_library(module_dir, cc=None, cflags=None) -> Path | None:
    """The module's intact library for this compiler and flags, or None (builds nothing)."""
    module_dir = Path(module_dir)
    _, src = _source(module_dir)
    lib = module_dir / library_name(build_key(src, compiler_command(cc), tuple(cflags or ())))
    return lib if intact(lib, hashlib.sha256(src).hexdigest()) else None


def build_library(module_dir, cc=None, cflags=None, store=None) -> Path:
    """Path of the module's compiled kernels (an intact library), building it if needed.

    cc: compiler command (default $CC or ``cc``); cflags: extra flags appended to
    DEFAULT_CFLAGS (a later -O wins); store: a directory of libraries shared by modules (see
    the module docstring). Raises ModelError when the sources differ from the module's
    MANIFEST.json, BuildError (command and stderr) when the compiler is missing or fails, and
    hpgen.cache.CacheUnwritable (a BuildError) when the directory is not writable.
    """
    module_dir = Path(module_dir)
    source, src = _source(module_dir)
    argv, extra = compiler_command(cc), tuple(cflags or ())
    name = library_name(build_key(src, argv, extra))
    digest = hashlib.sha256(src).hexdigest()
    target = module_dir / name
    if intact(target, digest):
        return target
    if store is None:
        return _compile(source, target, digest, argv, extra)
    built = _compile(source, Path(store) / name, digest, argv, extra)
    with cache.locked(module_dir, name):
        if not intact(target, digest):
            _link(built, target)
    return target


def _warn_corrupt(lib: Path) -> None:
    if lib.exists():
        print(f"hpgen: warning: {lib} does not match its build record (corrupt or "
              "incomplete); rebuilding it", file=sys.stderr)


def _link(built: Path, target: Path) -> None:
    """Put ``built`` and its record at ``target`` (a hard link, else a copy; atomic)."""
    for src, dst in ((built, target), (_record_path(built), _record_path(target))):
        tmp = dst.with_name(f".tmp{os.getpid()}{dst.name}")
        try:
            try:
                os.link(src, tmp)
            except OSError:
                shutil.copyfile(src, tmp)
            os.replace(tmp, dst)
        finally:
            if tmp.exists():
                tmp.unlink()


def _compile(source: Path, target: Path, digest: str, argv, extra) -> Path:
    """Compile ``source`` to ``target`` (with its record) unless an intact one is there."""
    if intact(target, digest):
        return target
    with cache.locked(target.parent, target.name):
        if intact(target, digest):          # another process built it while we waited
            return target
        _warn_corrupt(target)
        try:
            fd, tmp = tempfile.mkstemp(prefix=".tmp_kernels_", suffix=".so", dir=target.parent)
        except OSError as exc:
            raise cache.CacheUnwritable(target.parent, exc) from None
        os.close(fd)
        parts = translation_units(source.read_bytes())
        try:
            if parts == 1:
                _run([argv + list(DEFAULT_CFLAGS) + list(extra) + include_flags()
                      + ["-o", tmp, str(source)] + list(LIBS)])
            else:
                _compile_parts(source, tmp, parts, argv, extra)
            record = {"sha256": hashlib.sha256(Path(tmp).read_bytes()).hexdigest(),
                      "source_sha256": digest, "runtime_sha256": runtime_digest(),
                      "compiler": list(argv),
                      "cflags": list(DEFAULT_CFLAGS) + list(extra) + list(LIBS),
                      "translation_units": parts}
            write_file(_record_path(target), json.dumps(record, indent=1) + "\n")
            os.replace(tmp, target)
        finally:
            if os.path.exists(tmp):
                os.unlink(tmp)
    return target


def build_lazy_library(module_dir, cc=None, cflags=None) -> Path:
    """Path of the module's lazily built library (kernels.c with LAZY_FLAG: every kernel and
    hpgen_linearize), building it if needed; as build_library (the same errors)."""
    return build_library(module_dir, cc=cc, cflags=tuple(cflags or ()) + (LAZY_FLAG,))


def translation_units(source: bytes) -> int:
    """HPGEN_PARTS of a kernels.c split by hpgen.codegen.cparts, else 1."""
    m = _PARTS.search(source)
    return int(m.group(1)) if m else 1


def _compile_parts(source: Path, out: str, parts: int, argv, extra) -> None:
    """kernels.c compiled as its ``parts`` translation units (-DHPGEN_PART=k), at most
    os.cpu_count() compilers at a time, and the objects linked into ``out``."""
    objs = []
    try:
        for _ in range(parts):
            fd, obj = tempfile.mkstemp(prefix=".tmp_kernels_", suffix=".o",
                                       dir=Path(out).parent)
            os.close(fd)
            objs.append(obj)
        flags = argv + list(DEFAULT_CFLAGS) + list(extra) + include_flags()
        _run([flags + [f"-DHPGEN_PART={k}", "-c", "-o", objs[k], str(source)]
              for k in range(parts)], jobs=max(1, os.cpu_count() or 1))
        _run([argv + list(DEFAULT_CFLAGS) + list(extra) + ["-o", out] + objs + list(LIBS)])
    finally:
        for obj in objs:
            if os.path.exists(obj):
                os.unlink(obj)


def _run(cmds, jobs: int = 1) -> None:
    """Run the compiler commands ``cmds``, ``jobs`` at a time; BuildError (the command and
    its stderr) for the first that fails."""
    pending = list(cmds)
    running: list[tuple[list[str], subprocess.Popen]] = []
    try:
        while pending or running:
            while pending and len(running) < jobs:
                cmd = pending.pop(0)
                try:
                    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE,
                                            stderr=subprocess.PIPE, text=True,
                                            start_new_session=_SESSIONS)
                except FileNotFoundError:
                    raise BuildError("C compiler not found", command=cmd) from None
                except OSError as exc:
                    raise BuildError(f"C compiler could not run ({exc})", command=cmd) from None
                running.append((cmd, proc))
            cmd, proc = running.pop(0)
            try:
                _, err = proc.communicate(timeout=_TIMEOUT)
            except subprocess.TimeoutExpired:
                _kill(proc)
                raise BuildError(f"C compiler timed out after {_TIMEOUT} s", command=cmd) from None
            if proc.returncode != 0:
                raise BuildError(f"C compilation failed (exit status {proc.returncode})",
                                 command=cmd, stderr=err)
    finally:
        for _, proc in running:
            _kill(proc)


#: each compiler command in its own process group (POSIX), so that _kill reaches the
#: driver's children (cc1, as): killing the driver alone left cc1 compiling for minutes
_SESSIONS = hasattr(os, "killpg")


def _kill(proc: subprocess.Popen) -> None:
    """Stop a compiler command and every process of its group, and reap it."""
    try:
        if _SESSIONS:
            os.killpg(proc.pid, signal.SIGKILL)
        else:
            proc.kill()
    except (ProcessLookupError, PermissionError):
        pass
    proc.communicate()

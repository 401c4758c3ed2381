"""The static C runtime (hpgen/runtime/c) in the build: a module's library is keyed by the
runtime's sources too, so a changed runtime builds (and loads) a new library while the old
one stays valid for the old runtime; the build record names the runtime; the runtime refuses
to compile without a model."""
from __future__ import annotations

import ctypes
import json
import os
import shutil
import subprocess
import time

import pytest

from hpgen.runtime import build

from _toy_step import emitted, write_module

pytestmark = pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")


def _abi_of(lib) -> int:
    dims = (ctypes.c_longlong * 4)()
    ctypes.CDLL(str(lib)).hpgen_dims(dims)
    return dims[0]


def test_a_changed_runtime_builds_a_new_library(tmp_path, monkeypatch):
    runtime = tmp_path / "runtime"
    shutil.copytree(build.RUNTIME_DIR, runtime)
    monkeypatch.setattr(build, "RUNTIME_DIR", runtime)
    d = write_module(emitted()[1], tmp_path / "pkgs")
    first = build.build_library(d)
    record = json.loads(first.with_name(first.name + ".json").read_text())
    assert record["runtime_sha256"] == build.runtime_digest()
    # a changed runtime: another key, a new library compiled from the changed source
    header = runtime / "hpgen_runtime.h"
    text = header.read_text()
    assert "#define HPGEN_ABI " in text
    header.write_text(text.replace("#define HPGEN_ABI ", "#define HPGEN_ABI 1000 + "))
    second = build.build_library(d)
    assert second != first and second.is_file() and first.is_file()
    assert _abi_of(second) == 1000 + _abi_of(first)
    assert build.find_library(d) == second
    # the runtime as it was: the first library, intact, is found again without compiling
    header.write_text(text)
    assert build.find_library(d) == first == build.build_library(d)


def test_the_runtime_needs_a_model(tmp_path):
    src = tmp_path / "bare.c"
    src.write_text('#include "hpgen_runtime.c"\n')
    proc = subprocess.run(["cc", "-std=c99", *build.include_flags(), "-c", str(src), "-o",
                           str(tmp_path / "bare.o")], capture_output=True, text=True)
    assert proc.returncode != 0 and "define the model" in proc.stderr


def test_runtime_sources_are_the_shipped_files():
    names = [p.name for p in build.runtime_sources()]
    assert "hpgen_runtime.h" in names and "hpgen_runtime.c" in names
    # every other file is included by hpgen_runtime.c or by a file it includes
    included = "".join(p.read_text() for p in build.runtime_sources() if p.suffix == ".c")
    for name in names:
        if name not in ("hpgen_runtime.c", "hpgen_runtime.h"):
            assert f'#include "{name}"' in included, name


@pytest.mark.skipif(not hasattr(os, "killpg"), reason="process groups are POSIX")
def test_a_timed_out_compiler_is_stopped_with_its_children(tmp_path, monkeypatch):
    """A compiler driver that times out is stopped together with the processes it started
    (cc's cc1 and as): the BuildError names the timeout and no child keeps running."""
    pidfile = tmp_path / "child.pid"
    monkeypatch.setattr(build, "_TIMEOUT", 1)
    cmd = ["sh", "-c", f"sleep 60 & echo $! > {pidfile}; wait"]
    with pytest.raises(build.BuildError, match="timed out after 1 s"):
        build._run([cmd])
    child = int(pidfile.read_text())
    for _ in range(50):                 # SIGKILL is delivered asynchronously
        if not _alive(child):
            break
        time.sleep(0.02)
    assert not _alive(child)


def _alive(pid: int) -> bool:
    """Whether process ``pid`` exists and is not a zombie."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(") ")[1][0] != "Z"
    except FileNotFoundError:
        return False

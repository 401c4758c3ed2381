"""A family module's lazily built second library (hpgen.codegen.csource.LAZY_KERNELS,
hpgen.runtime.build.build_lazy_library): the step library leaves step_partials and
hpgen_linearize out; the first linearize builds the complete library from the cache entry's
kernels.c with the C compiler alone, atomically, rebuilding a missing or damaged one; its
results are bitwise those of a module compiled without the split. Checked on the 2-link
pendulum chain (a family module)."""
from __future__ import annotations

import ctypes
import hashlib
import importlib
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

import hpgen
from hpgen.codegen import csource
from hpgen.errors import BuildError
from hpgen.model import load_model
from hpgen.runtime import build

from conftest import EXAMPLES, child_process

CHAIN = EXAMPLES / "pendulum_chain.yaml"          # N = 2
ROOT = EXAMPLES.parent
needs_cc = pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")

SIG = "(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem)"


def _fn(k: int, calls: list[int]) -> str:
    body = [f"  if (casadi_f{c}(arg, res, iw, w, 0)) return 1;" for c in calls]
    return "\n".join([f"/* f{k} */", f"static int casadi_f{k}{SIG} {{", *body,
                      "  return 0;", "}"])


def _export(name: str, k: int) -> str:
    return "\n".join([f"CASADI_SYMBOL_EXPORT int {name}{SIG}{{",
                      f"  return casadi_f{k}(arg, res, iw, w, mem);", "}"])


def test_only_what_the_lazy_kernels_alone_reach_is_guarded():
    # f0 shared by step and partials, f1 partials' own callee, f2 partials, f3 step
    code = "\n".join([_fn(0, []), _fn(1, []), _fn(2, [0, 1]), _fn(3, [0]),
                      _export("step", 3), _export("partials", 2), ""])
    out = csource.guard_lazy_functions(code, ["partials"])
    lines = out.split("\n")

    def guarded(line: str) -> bool:
        depth = 0
        for text in lines[:lines.index(line)]:
            depth += text == csource.LAZY_BEGIN
            depth -= text == csource.LAZY_END
        return depth == 1

    assert guarded(f"static int casadi_f1{SIG} {{") and guarded(f"static int casadi_f2{SIG} {{")
    assert guarded(f"CASADI_SYMBOL_EXPORT int partials{SIG}{{")
    assert not guarded(f"static int casadi_f0{SIG} {{")
    assert not guarded(f"static int casadi_f3{SIG} {{")
    assert not guarded(f"CASADI_SYMBOL_EXPORT int step{SIG}{{")
    assert "\n".join(t for t in lines if t not in (csource.LAZY_BEGIN, csource.LAZY_END)) == code
    assert csource.guard_lazy_functions(code, ["nothing"]) == code


@pytest.fixture(scope="module")
def chain(tmp_path_factory):
    if shutil.which("cc") is None:
        pytest.skip("no C compiler")
    cache = tmp_path_factory.mktemp("lazy-cache")
    return hpgen.build(CHAIN, cache_dir=cache, backend="c")


def _lazy_libraries(module_dir):
    step = build.find_library(module_dir)
    return [p for p in module_dir.glob("_kernels_*.so") if p != step]


def _symbols(lib) -> set[str]:
    handle = ctypes.CDLL(str(lib))
    return {s for s in ("hpgen_linearize", "hpgen_kernel_step_partials", "hpgen_advance",
                        "hpgen_kernel_energy") if hasattr(handle, s)}


def test_the_step_library_leaves_the_lazy_code_out_and_a_run_builds_nothing(chain):
    d = chain.module_dir
    assert csource.LAZY_BEGIN in (d / "kernels.c").read_text()
    assert _symbols(build.find_library(d)) == {"hpgen_advance", "hpgen_kernel_energy"}
    for lib in _lazy_libraries(d):
        lib.unlink()
    sc = load_model(CHAIN).scene
    chain.load().simulate(sc.g0, sc.h, 5, xi0=sc.xi0)
    assert _lazy_libraries(d) == []


def _linearize_in_child(module_dir) -> str:
    """A fresh process loading the cache entry, running and linearizing it: prints the
    compile-time modules it imported and the sum of A."""
    code = (
        "import sys, numpy as np\n"
        "from hpgen.runtime import load\n"
        f"integ = load({str(module_dir)!r})\n"
        "tr = integ.simulate(np.eye(integ.n), 0.01, 3, xi0=np.linspace(0.1, 0.6, integ.d))\n"
        "A = integ.linearize(tr)\n"
        "print([m for m in ('casadi', 'sympy', 'jinja2') if m in sys.modules])\n"
        "print(repr(float(A.sum())))\n")
    with child_process([sys.executable, "-c", code], cwd=ROOT,
                       env=dict(os.environ, PYTHONPATH=str(ROOT))) as proc:
        out, err = proc.communicate(timeout=600)
    assert proc.returncode == 0, err
    return out


def test_the_first_linearize_builds_it_with_the_c_compiler_only(chain):
    d = chain.module_dir
    for lib in _lazy_libraries(d):
        lib.unlink()
    out = _linearize_in_child(d).split("\n")
    assert out[0] == "[]"
    (lazy,) = _lazy_libraries(d)
    assert _symbols(lazy) == {"hpgen_linearize", "hpgen_kernel_step_partials",
                              "hpgen_advance", "hpgen_kernel_energy"}
    assert not list(d.glob(".tmp*"))


@pytest.mark.parametrize("damage", ["missing", "flipped", "truncated"])
def test_a_missing_or_damaged_lazy_library_is_rebuilt(chain, damage):
    d = chain.module_dir
    lazy = build.build_lazy_library(d)
    good = lazy.read_bytes()
    if damage == "missing":
        lazy.unlink()
    elif damage == "flipped":
        data = bytearray(good)
        data[len(data) // 2] ^= 0xFF
        lazy.write_bytes(bytes(data))
    else:
        lazy.write_bytes(good[:len(good) // 3])
    sc = load_model(CHAIN).scene
    integ = chain.load()
    integ.linearize(integ.simulate(sc.g0, sc.h, 3, xi0=sc.xi0))
    assert lazy.read_bytes() == good


def test_two_processes_racing_both_end_with_a_good_library(chain):
    d = chain.module_dir
    for lib in _lazy_libraries(d):
        lib.unlink()
    code = ("import sys; from hpgen.runtime import build; "
            "print(build.build_lazy_library(sys.argv[1]))")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    procs = [subprocess.Popen([sys.executable, "-c", code, str(d)], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, cwd=ROOT, env=env)
             for _ in range(2)]
    outs = [p.communicate(timeout=600) for p in procs]
    assert [p.returncode for p in procs] == [0, 0], outs
    paths = {o.strip() for o, _ in outs}
    assert len(paths) == 1
    lib = build.build_lazy_library(d)
    assert str(lib) in paths
    assert build.intact(lib, hashlib.sha256((d / "kernels.c").read_bytes()).hexdigest())
    assert not list(d.glob(".tmp*"))


def test_a_failing_lazy_build_is_a_build_error_naming_its_command(chain, tmp_path):
    cc = tmp_path / "cc-no-lazy"
    cc.write_text('#!/bin/sh\ncase "$*" in *HPGEN_LAZY_LIBRARY*) echo "no lazy here" >&2; '
                  'exit 1;; esac\nexec cc "$@"\n')
    cc.chmod(0o755)
    with pytest.raises(BuildError, match="C compilation failed") as exc:
        build.build_lazy_library(chain.module_dir, cc=str(cc))
    assert build.LAZY_FLAG in exc.value.command and "no lazy here" in exc.value.stderr


def test_the_split_computes_bitwise_what_one_library_does(chain, tmp_path, monkeypatch):
    sc = load_model(CHAIN).scene
    lazy = chain.load()
    a = lazy.simulate(sc.g0, sc.h, 20, xi0=sc.xi0)
    monkeypatch.setattr(importlib.import_module("hpgen.codegen.emit"), "LAZY_KERNELS", ())
    monkeypatch.setattr(csource, "LAZY_KERNELS", ())
    whole = hpgen.build(CHAIN, cache_dir=tmp_path, backend="c")
    assert csource.LAZY_BEGIN not in (whole.module_dir / "kernels.c").read_text()
    assert "hpgen_linearize" in _symbols(build.find_library(whole.module_dir))
    one = whole.load()
    b = one.simulate(sc.g0, sc.h, 20, xi0=sc.xi0)
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
    assert np.array_equal(lazy.linearize(a), one.linearize(b))

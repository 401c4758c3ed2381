"""kernels.c's CasADi part: in a family's module the functions of the cold kernels only are
marked for -O1, with bitwise the same results."""
from __future__ import annotations

import shutil
from importlib import import_module

import numpy as np
import pytest

import hpgen
from hpgen.codegen.csource import cold_functions, mark_cold_functions

from _toy_step import emitted

SIG = "(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {"


def _fn(k: int, body: str, comment: str | None = None) -> str:
    head = f"/* {comment} */\n" if comment else ""
    return f"{head}static int casadi_f{k}{SIG}\n{body}\n}}\n"


def _export(name: str, k: int) -> str:
    return (f"CASADI_SYMBOL_EXPORT int {name}(const casadi_real** arg, casadi_real** res, "
            f"casadi_int* iw, casadi_real* w, int mem){{\n  return casadi_f{k}(arg, res, iw, w, "
            "mem);\n}\n")


DEFINES = "".join(f"#define casadi_f{k} CASADI_PREFIX(f{k})\n" for k in range(6))
CODE = DEFINES + "".join([
    _fn(0, "  res[0][0]=arg[0][0];", "body:(i0)->(o0)"),
    _fn(1, "  res[0][0]=arg[0][0];", "body_again:(i0)->(o0)"),   # f0 printed again
    _fn(2, "  if (casadi_f0(arg, res, iw, w, 0)) return 1;", "uses f0"),
    _fn(3, "  if (casadi_f1(arg, res, iw, w, 0)) return 1;", "uses f1"),
    _fn(4, "  if (casadi_f3(arg, res, iw, w, 0)) return 1;\n  res[0][1]=2.;", "partials"),
    _fn(5, "  res[0][0]=3.;", "analysis"),
    _export("step", 2), _export("partials", 4), _export("energy", 5)])


def test_only_functions_no_hot_kernel_reaches_are_marked_cold():
    # the step reaches f2 and f0; the partials f4, f3 and f1 (the copy of f0); energy f5
    assert cold_functions(CODE, ["partials", "energy"]) == {
        f"casadi_f{k}" for k in (1, 3, 4, 5)}
    assert cold_functions(CODE, ["step", "partials", "energy"]) == {
        f"casadi_f{k}" for k in range(6)}
    assert cold_functions(CODE + _fn(6, "  res[0][0]=4.;"), ["partials", "energy"]) == {
        f"casadi_f{k}" for k in (1, 3, 4, 5)}                 # f6, called by no one: the runtime's
    marked = mark_cold_functions(CODE, ["partials", "energy"])
    blocks = marked.split("HPGEN_COLD_BEGIN\n")[1:]
    assert len(blocks) == 4 and all("HPGEN_COLD_END" in b for b in blocks)
    cold = [b.split("HPGEN_COLD_END")[0] for b in blocks]
    assert [c.split("\n")[0] for c in cold] == ["/* body_again:(i0)->(o0) */", "/* uses f1 */",
                                                 "/* partials */", "/* analysis */"]
    assert all(c.count(SIG) == 1 for c in cold)
    assert marked.replace("HPGEN_COLD_BEGIN\n", "").replace("HPGEN_COLD_END\n", "") == CODE
    assert mark_cold_functions(CODE, []) == CODE


def test_small_modules_print_no_cold_marks():
    assert "HPGEN_COLD" not in emitted()[1].file("kernels.c")


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")
def test_a_family_module_marks_cold_code_with_bitwise_the_same_runs(tmp_path, monkeypatch):
    from conftest import EXAMPLES
    from hpgen.model import load_model
    chain = EXAMPLES / "pendulum_chain.yaml"
    new = hpgen.build(chain, cache_dir=tmp_path / "new", backend="c")
    source = (new.module_dir / "kernels.c").read_text()
    assert "HPGEN_COLD_BEGIN\n/* step_partials:" in source
    csource = import_module("hpgen.codegen.csource")
    monkeypatch.setattr(csource, "mark_cold_functions", lambda code, roots: code)
    old = hpgen.build(chain, cache_dir=tmp_path / "old", backend="c")
    plain = (old.module_dir / "kernels.c").read_text()
    assert "HPGEN_COLD_BEGIN\n" not in plain
    # the marks are all that differs in the CasADi functions
    assert source.replace("HPGEN_COLD_BEGIN\n", "").replace("HPGEN_COLD_END\n", "") \
        .count(SIG) == plain.count(SIG)
    sc = load_model(chain).scene
    a = old.load().simulate(sc.g0, sc.h, 30, xi0=sc.xi0)
    b = new.load().simulate(sc.g0, sc.h, 30, xi0=sc.xi0)
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
    assert np.array_equal(old.load().linearize(a), new.load().linearize(b))

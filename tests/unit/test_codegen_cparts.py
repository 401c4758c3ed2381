"""A family module's kernels.c split into translation units (hpgen.codegen.cparts) compiled in
parallel and linked: the same file compiles as one unit, and both libraries compute bitwise
the same."""
from __future__ import annotations

import ctypes
import importlib
import json
import shutil

import numpy as np
import pytest

import hpgen
from hpgen.codegen import cparts
from hpgen.errors import BuildError
from hpgen.runtime import build

SIG = "(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem)"
needs_cc = pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")


def _fn(k: int, body: list[str], comment: str, cold: bool = False) -> str:
    text = f"/* {comment} */\nstatic int casadi_f{k}{SIG} {{\n" + "\n".join(body) + "\n}\n"
    return f"HPGEN_COLD_BEGIN\n{text}HPGEN_COLD_END\n" if cold else text


def _long(n: int, out: int) -> list[str]:
    """n lines of straight-line code: res[0][out] = arg[0][0] * s^n with s = casadi_sq(1.5)."""
    body = ["  casadi_real a = arg[0][0];", "  casadi_real s = casadi_sq(1.5);"]
    body += ["  a = a * s;"] * n
    return body + [f"  res[0][{out}] = a + casadi_s0[1];", "  return 0;"]


#: CasADi-shaped code: a helper, a constant array, exported functions, small and large ones
CODE = "\n".join([
    "#include <math.h>",
    "#define casadi_real double",
    "#define casadi_int long long int",
    "#define CASADI_SYMBOL_EXPORT",
    "casadi_real casadi_sq(casadi_real x) { return x*x;}",
    "",
    "static const casadi_int casadi_s0[3] = ",
    "  {1, 2,",
    "  3};",
    "",
    _fn(0, _long(cparts.MIN_LINES + 300, 0), "big:(i0)->(o0)"),
    _fn(1, _long(cparts.MIN_LINES + 200, 1), "big_too:(i0)->(o0)"),
    _fn(2, _long(3, 2), "small:(i0)->(o0)"),
    _fn(3, ["  if (casadi_f0(arg, res, iw, w, 0)) return 1;",
            "  if (casadi_f1(arg, res, iw, w, 0)) return 1;",
            "  if (casadi_f2(arg, res, iw, w, 0)) return 1;", "  return 0;"],
        "step:(i0)->(o0[3])"),
    _fn(4, _long(cparts.MIN_LINES + 300, 0), "cold:(i0)->(o0)", cold=True),
    f"CASADI_SYMBOL_EXPORT int step{SIG}{{",
    "  return casadi_f3(arg, res, iw, w, mem);",
    "}",
    f"CASADI_SYMBOL_EXPORT int cold{SIG}{{",
    "  return casadi_f4(arg, res, iw, w, mem);",
    "}",
    "CASADI_SYMBOL_EXPORT int n_in(void) { return 1; }",
    ""])


def _kernels_c(code: str) -> str:
    """A kernels.c around CasADi-shaped code as kernels.c.j2 lays it out: part 0 holds the
    rest; hpgen_kernel_step exports the step."""
    return "\n".join([
        "#define HPGEN_COLD_BEGIN", "#define HPGEN_COLD_END",
        "#pragma GCC visibility push(hidden)", code, "#pragma GCC visibility pop",
        "#if HPGEN_IN_PART(0)" if "HPGEN_PARTS" in code else "",
        "__attribute__((visibility(\"default\"))) int hpgen_kernel_step(const double* x, "
        "double* y) {",
        "    const casadi_real* arg[1] = {x}; casadi_real* res[1] = {y};",
        "    int a = step(arg, res, 0, 0, 0);",
        "    double z = 0; casadi_real* r2[1] = {&z};",
        "    return a + cold(arg, r2, 0, 0, 0) + (z != y[0]);",
        "}",
        "#endif" if "HPGEN_PARTS" in code else "", ""])


def test_large_functions_move_to_other_parts_with_what_they_use():
    split = cparts.split_casadi_code(CODE)
    assert split.startswith(cparts.MACROS.format(parts=cparts.PARTS))
    lines = split.split("\n")

    def guard_of(line: str) -> str | None:
        """The #if in force at ``line`` (None: all parts)."""
        guard = None
        for text in lines[:lines.index(line)]:
            if text.startswith("#if HPGEN_IN_PART"):
                guard = text
            elif text == "#endif":
                guard = None
        return guard

    def definition(k: int) -> str:
        return next(t for t in lines if t.endswith(f"casadi_f{k}{SIG} {{"))

    # the large functions go to part 1 (part 0's runtime outweighs them), extern there,
    # declared before the first function
    for k in (0, 1, 4):
        assert definition(k).startswith("HPGEN_SHARED int ")
        assert guard_of(definition(k)) == "#if HPGEN_IN_PART(1)"
        assert f"HPGEN_SHARED int casadi_f{k}{SIG};" in lines
    assert "HPGEN_COLD_BEGIN" in split.split(definition(4))[0].split("#if HPGEN_IN_PART(1)")[-1]
    # the small function, the caller and the exports stay in part 0, static unless called
    # from another part
    assert guard_of(f"static int casadi_f2{SIG} {{") == "#if HPGEN_IN_PART(0)"
    assert guard_of(f"static int casadi_f3{SIG} {{") == "#if HPGEN_IN_PART(0)"
    assert guard_of("CASADI_SYMBOL_EXPORT int n_in(void) { return 1; }") == \
        "#if HPGEN_IN_PART(0)"
    # the helper: a private copy per part; the array: in every part that reads it
    assert "HPGEN_PRIVATE casadi_real casadi_sq(casadi_real x) { return x*x;}" in lines
    assert guard_of("static const casadi_int casadi_s0[3] = ") is None
    # nothing but the guards, declarations and storage classes differ
    body = split[len(cparts.MACROS.format(parts=cparts.PARTS)):].split("\n")
    plain = [t.replace("HPGEN_PRIVATE ", "").replace("HPGEN_SHARED ", "static ")
             for t in body if not (t.startswith(("#if HPGEN_IN_PART", "#endif", "/* functions "))
                                   or t.endswith(";") and t.startswith("HPGEN_SHARED"))]
    assert "\n".join(plain) == CODE


def test_small_code_is_not_split():
    small = CODE.replace("\n  a = a * s;", "")
    assert cparts.split_casadi_code(small) == small


def test_parts_balance_the_cost_longest_first():
    parts = cparts.assign_parts({"a": 5.0, "b": 4.0, "c": 3.0, "d": 3.0}, 2, 2.0)
    assert parts == {"a": 1, "b": 0, "c": 1, "d": 0}          # loads 2+4+3 = 9, 5+3 = 8
    assert cparts.assign_parts({"a": 1.0}, 2, 100.0) == {"a": 1}


def _library(tmp_path, name: str, source: str):
    d = tmp_path / name
    d.mkdir()
    (d / "kernels.c").write_text(source)
    lib = build.build_library(d)
    f = ctypes.CDLL(str(lib)).hpgen_kernel_step
    f.argtypes = [ctypes.POINTER(ctypes.c_double)] * 2
    y = (ctypes.c_double * 3)()
    assert f((ctypes.c_double * 1)(0.7), y) == 0
    return lib, list(y)


@needs_cc
def test_split_and_single_unit_libraries_compute_the_same(tmp_path):
    split = _kernels_c(cparts.split_casadi_code(CODE))
    assert build.translation_units(split.encode()) == cparts.PARTS
    assert build.translation_units(_kernels_c(CODE).encode()) == 1
    lib, y = _library(tmp_path, "split", split)
    assert json.loads(lib.with_name(lib.name + ".json").read_text())[
        "translation_units"] == cparts.PARTS
    single_lib, single = _library(tmp_path, "single", _kernels_c(CODE))
    assert y == single and y[2] == 0.7 * 2.25 ** 3 + 2
    # the split file compiled without -DHPGEN_PART is one unit computing the same
    d = tmp_path / "one"
    d.mkdir()
    (d / "kernels.c").write_text(split.replace("#define HPGEN_PARTS 2\n", ""))
    assert _library(tmp_path, "one2", (d / "kernels.c").read_text())[1] == y
    assert not list((tmp_path / "split").glob("*.o"))          # objects removed


@needs_cc
def test_a_failing_part_is_a_build_error_naming_its_command(tmp_path):
    bad = _kernels_c(cparts.split_casadi_code(CODE)).replace(
        "res[0][0] = a + casadi_s0[1];", "res[0][0] = a + undefined_name;")
    d = tmp_path / "bad"
    d.mkdir()
    (d / "kernels.c").write_text(bad)
    with pytest.raises(BuildError, match="C compilation failed") as exc:
        build.build_library(d)
    assert "-DHPGEN_PART=1" in exc.value.command and "undefined_name" in exc.value.stderr
    assert not list(d.glob(".tmp*")) and not list(d.glob("*.so"))


@needs_cc
def test_a_split_family_module_runs_bitwise_as_one_unit(tmp_path, monkeypatch):
    from conftest import EXAMPLES
    from hpgen.model import load_model
    emit = importlib.import_module("hpgen.codegen.emit")
    chain = EXAMPLES / "pendulum_chain.yaml"           # N = 2
    new = hpgen.build(chain, cache_dir=tmp_path / "new", backend="c")
    assert build.translation_units((new.module_dir / "kernels.c").read_bytes()) == 2
    monkeypatch.setattr(emit, "split_casadi_code", lambda code: code)
    old = hpgen.build(chain, cache_dir=tmp_path / "old", backend="c")
    assert build.translation_units((old.module_dir / "kernels.c").read_bytes()) == 1
    sc = load_model(chain).scene
    a = old.load().simulate(sc.g0, sc.h, 30, xi0=sc.xi0)
    b = new.load().simulate(sc.g0, sc.h, 30, xi0=sc.xi0)
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
    assert np.array_equal(old.load().linearize(a), new.load().linearize(b))

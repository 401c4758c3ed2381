"""hpgen.abi is the one contract between generated code and the runtime: the static C runtime
(hpgen/runtime/c), the emitted C, the Python mirror of the Newton loop, the ctypes structs and
the meta.json loader all agree with it."""
from __future__ import annotations

import ast
import json
import re
import struct

import pytest

from conftest import ROOT
from hpgen import abi

GENERATED = ROOT / "generated"
#: a golden module (tests/regression/test_generated keeps it current)
MODULE = GENERATED / "free_rigid_body_stormer_verlet_cay_truncated"
#: the static C runtime every kernels.c includes
RUNTIME = ROOT / "hpgen" / "runtime" / "c"


def _header() -> str:
    return (RUNTIME / "hpgen_runtime.h").read_text()


def _defines(src: str) -> dict:
    return dict(re.findall(r"^#define (HPGEN_[A-Z0-9_]+) (.+)$", src, re.M))


def _bits(x: float) -> bytes:
    return struct.pack("<d", x)


def test_runtime_status_codes_and_abi_version():
    defs = _defines(_header())
    assert int(defs["HPGEN_ABI"]) == abi.ABI_VERSION
    for code, name, message in abi.STATUS:
        assert int(defs[f"HPGEN_{name}"].strip("()")) == code, name
        assert f"HPGEN_{name} = {code}: {message}" in _header(), name
    codes = [code for code, _, _ in abi.STATUS]
    assert len(set(codes)) == len(codes) and set(abi.MESSAGES) == set(codes)


def test_runtime_newton_constants_read_back_bitwise():
    src = _header()
    defs = _defines(src)
    for macro, value in abi.C_CONSTANTS.items():
        assert defs[macro] == abi.c_literal(value), macro
        if isinstance(value, float):
            assert _bits(float(defs[macro])) == _bits(value), macro
    # the predictor's history and its coefficient table (rows zero-padded to HPGEN_PH)
    H = abi.PREDICTOR_HISTORY
    assert int(defs["HPGEN_PH"]) == H
    table = re.search(r"static const double hpgen_pc\[HPGEN_PH\]\[HPGEN_PH\] = \{(.*?)\};",
                      src, re.S).group(1)
    rows = [[float(x) for x in r.split(",")] for r in re.findall(r"\{([^{}]*)\}", table)]
    want = [list(c) + [0.0] * (H - len(c)) for c in abi.PREDICTOR_COEFFICIENTS]
    assert [[_bits(x) for x in r] for r in rows] == [[_bits(x) for x in r] for r in want]
    # the record velocity's Newton takes its tolerance and cap from those macros
    runs = (RUNTIME / "hpgen_advance.c").read_text()
    vel = runs[runs.index("static int hpgen_velocity("):]
    vel = vel[:vel.index("\n}\n")]
    assert "it <= HPGEN_VELOCITY_MAXIT; ++it" in vel
    assert "if (dn <= HPGEN_VELOCITY_TOL * (1.0 + xn))" in vel


def test_emitted_c_kernel_table():
    from _toy_step import emitted
    step, gm = emitted()
    src, meta = gm.file("kernels.c"), json.loads(gm.file("meta.json"))
    exported = re.findall(r"^HPGEN_EXPORT int hpgen_kernel_(\w+)\(([^)]*)\)", src, re.M)
    assert tuple(name for name, _ in exported) == abi.KERNEL_NAMES
    w = abi.record_width(meta["record"], meta["n"], meta["d"])
    size = abi.sizes(meta["n"], meta["d"], meta["nz"], w)
    for spec in abi.KERNELS:
        # /* name(a[k], ...) -> (b[k], ...) */ above each kernel: the sizes, in order
        m = re.search(rf"^/\* {spec.name}\(([^)]*)\) -> \(([^)]*)\) \*/$", src, re.M)
        ins, outs = ([int(x) for x in re.findall(r"\[(\d+)\]", part)] for part in m.groups())
        assert ins == [size[s] for s in spec.inputs], spec.name
        assert outs == [size[s] for s in spec.outputs], spec.name
        args = dict(exported)[spec.name].split(",")
        assert len(args) == len(spec.inputs) + len(spec.outputs), spec.name
    # the model's sizes, and the runtime included after the kernels
    defs = _defines(src)
    assert [int(defs[f"HPGEN_{k}"]) for k in ("N", "D", "NZ")] == [step.n, step.d, step.nz]
    assert src.rstrip().endswith('#include "hpgen_runtime.c"')


def _c_struct(src: str, name: str) -> list:
    body = re.search(rf"typedef struct {name} \{{(.*?)\}} {name};", src, re.S).group(1)
    return [(f, "d" if t == "double" else "q")
            for t, f in re.findall(r"^\s*(long long|double) (\w+);", body, re.M)]


def test_c_structs_match_the_ctypes_side():
    from hpgen.runtime.cstructs import _Options, _Status
    src = _header()
    assert _c_struct(src, "hpgen_status") == list(abi.STATUS_FIELDS)
    assert _c_struct(src, "hpgen_options") == list(abi.OPTIONS_FIELDS)
    assert [f for f, _ in _Status._fields_] == [f for f, _ in abi.STATUS_FIELDS]
    assert [f for f, _ in _Options._fields_] == [f for f, _ in abi.OPTIONS_FIELDS]


def test_contract_literals_live_in_the_header_only():
    """The constants and codes are written once in C, in hpgen_runtime.h; the template and
    the runtime's other files use the macros."""
    texts = {p.name: p.read_text() for p in RUNTIME.glob("*.c")}
    texts["kernels.c.j2"] = (ROOT / "templates" / "kernels.c.j2").read_text()
    for name, text in texts.items():
        code = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
        for lit in ("1e-14", "1e-11", "0.05", "0.01", "<= 50"):
            assert lit not in code, (name, lit)
        assert not re.search(r"#define HPGEN_(ABI|OK|NO_CONVERGENCE|NONFINITE|DOMAIN|RECORD|"
                             r"INVALID|ROUNDOFF_FLOOR|THETA_MAX|SIMPLIFIED_TOL|THETA_FLOOR|PH|"
                             r"VELOCITY_TOL|VELOCITY_MAXIT) ", text), name


def test_python_mirror_takes_the_same_constants():
    from hpgen.codegen import pylinear
    from hpgen.runtime import loop, newton, record_row
    for name in ("OK", "NO_CONVERGENCE", "NONFINITE", "DOMAIN", "ROUNDOFF_FLOOR",
                 "THETA_MAX", "SIMPLIFIED_TOL", "THETA_FLOOR", "DEFAULT_TOL", "DEFAULT_MAXIT",
                 "REFRESH"):
        assert getattr(newton, name) is getattr(abi, name), name
    assert loop.PREDICTOR_COEFFICIENTS is abi.PREDICTOR_COEFFICIENTS
    assert loop.PREDICTOR_HISTORY is abi.PREDICTOR_HISTORY
    for name in ("OK", "NONFINITE", "RECORD"):     # the run loop's
        assert getattr(loop, name) is getattr(abi, name), name
    for name in ("OK", "RECORD", "ROUNDOFF_FLOOR", "VELOCITY_TOL", "VELOCITY_MAXIT"):
        assert getattr(record_row, name) is getattr(abi, name), name    # the record row's
    assert pylinear.UNROLL_MAX is abi.UNROLL_MAX
    assert list(loop.new_status()) == [f for f, _ in abi.STATUS_FIELDS]
    # no bare tolerance or iteration cap left in the Python mirror
    for mod in (newton, loop, record_row):
        tree = ast.parse(open(mod.__file__).read())
        nums = {n.value for n in ast.walk(tree) if isinstance(n, ast.Constant)
                and type(n.value) in (int, float)}
        assert not nums & {1e-14, 1e-11, 0.05, 0.01, 50, 51}, mod.__name__


@pytest.mark.parametrize("x", [1e-14, 1e-11, 0.05, 0.01, 0.1, 1 / 3, 2.0 ** -1074, 1e308, 50])
def test_c_literal_reads_back_bitwise(x):
    text = abi.c_literal(x)
    assert (int(text) if isinstance(x, int) else float(text)) == x
    if isinstance(x, float):
        assert _bits(float(text)) == _bits(x) and re.search(r"[.e]", text)


@pytest.mark.parametrize("x", [float("nan"), float("inf"), True, "1"])
def test_c_literal_refuses_what_c_cannot_read(x):
    with pytest.raises((TypeError, ValueError)):
        abi.c_literal(x)


def test_record_width_conventions():
    assert abi.record_width((("g", 0, (3, 3)), ("mu", 9, (3,)), ("E", 12, ())), 3, 3) == 13
    for bad in ((), (("g", 1, ()),), (("a", 0, ()), ("a", 1, ())), (("1x", 0, ()),),
                (("v", 0, (2,)),)):
        with pytest.raises(ValueError):
            abi.record_width(bad, 3, 3)


def test_loader_refuses_an_older_meta_format(tmp_path):
    from hpgen.errors import ModelError
    from hpgen.runtime import read_meta
    meta = json.loads((MODULE / "meta.json").read_text())
    assert meta["format"] == abi.META_FORMAT
    read_meta(MODULE)
    meta["format"] = abi.META_FORMAT - 1
    (tmp_path / "meta.json").write_text(json.dumps(meta))
    old = abi.META_FORMAT - 1
    with pytest.raises(ModelError, match=rf"meta\.json.*format: .*format {old}.*recompile") as e:
        read_meta(tmp_path)
    assert "\n" not in str(e.value)

"""hpgen.codegen on a hand-built DiscreteStep (tests/unit/_toy_step.py)."""
from __future__ import annotations

import json
import math
import shutil
import subprocess

import casadi as ca
import jinja2.meta
import numpy as np
import pytest

import hpgen
from hpgen.codegen import (META_FORMAT, CodegenError, emit, environment, module_name, template_contexts,
                           template_dir)
from hpgen.codegen.pysource import kernel_lines
from hpgen.derive.step import DiscreteStep, Kernel
from hpgen.runtime.build import include_flags

from _toy_step import emitted, integrator, module_dir, toy_info, toy_step

STRICT_FLAGS = ["-std=c99", "-O2", "-Wall", "-Werror", "-fPIC", "-shared"]


def _casadi_eval(f, args):
    out = f.call([ca.DM(a) for a in args])
    return [np.array(o.full()).ravel(order="F") for o in out]


def _random_args(f, rng):
    return [rng.uniform(-1.5, 1.5, f.numel_in(i)) for i in range(f.n_in())]


def test_emit_is_deterministic_and_complete():
    step, gm = emitted()
    again = emit(toy_step(), toy_info(module="toy_plain"))
    assert gm == again
    assert [p for p, _ in gm.files] == ["__init__.py", "kernels.c", "kernels.py", "meta.json",
                                        "model.yaml"]
    for path, text in gm.files:
        assert "/tmp" not in text and "/work" not in text, path


def test_header_names_model_options_version_hash():
    _, gm = emitted()
    info = toy_info()
    for path in ("kernels.c", "kernels.py", "__init__.py"):
        head = "\n".join(gm.file(path).splitlines()[:7])
        assert head.startswith("/*" if path.endswith(".c") else "# "), path
        for needle in ("free_rigid_body", "tableau=euler-poincare", "tau=cay", "rkmk=exact",
                       f"hpgen version: {hpgen.__version__}",
                       f"content hash (normalized model + options): {info['hash']}"):
            assert needle in head, (path, needle)
    assert gm.file("model.yaml") == info["model_source"]


def test_meta_json():
    step, gm = emitted()
    text = gm.file("meta.json")
    meta = json.loads(text)
    assert text.endswith("\n") and text == json.dumps(meta, sort_keys=True, indent=2) + "\n"
    assert meta["format"] == META_FORMAT == 5 and meta["module"] == "toy_plain"
    assert meta["jacobian"] == {"storage": "dense"}
    assert meta["backend"] == "c" and meta["group"] == "SO3"
    assert (meta["n"], meta["d"], meta["nz"], meta["reduced"]) == (3, 3, 3, True)
    assert meta["unknowns"] == [["xi", 0, 3]]
    upd = meta["kernels"]["update"]
    assert upd["inputs"] == [["z", 3], ["g", 9], ["p", 3], ["h", 1]]
    assert upd["outputs"] == [["g1", 9], ["p1", 3]]
    assert upd["instructions"] == step.kernel("update").function.n_instructions() > 0
    assert set(meta["c_work"]["residual"]) == {"sz_arg", "sz_res", "sz_iw", "sz_w"}


def test_module_name():
    assert module_name("heavy_top", "gauss2", "exp", "exact") == "heavy_top_gauss2_exp_exact"
    assert module_name("rb", "stormer-verlet", "cay", "exact") == "rb_stormer_verlet_cay_exact"
    with pytest.raises(CodegenError):
        module_name("2body", "gauss2", "exp", "exact")
    with pytest.raises(CodegenError):
        module_name("x" * 130, "gauss2", "exp", "exact")


@pytest.mark.parametrize("bad", [{"module": "bad-name"}, {"module": "a/../b"},
                                 {"module": "class"}, {"hash": "xyz"}, {"backend": "fortran"},
                                 {"options": {"tableau": "gauss2"}}])
def test_info_is_validated(bad):
    with pytest.raises(CodegenError):
        emit(toy_step(), toy_info(**bad))


def test_header_text_is_sanitised():
    step = toy_step()
    gm = emit(step, toy_info(model_name='evil */ """\n\\ x'))
    c = gm.file("kernels.c")
    assert c.index("*/") > c.index("content hash")      # the first */ closes the header
    compile(gm.file("kernels.py"), "kernels.py", "exec")
    compile(gm.file("__init__.py"), "__init__.py", "exec")


def test_template_variables_match_contexts():
    step, _ = emitted()
    contexts = template_contexts(step, toy_info())
    env = environment()
    names = {p.name for p in template_dir().glob("*.j2")}
    assert names == set(contexts)
    for name, ctx in contexts.items():
        source = env.loader.get_source(env, name)[0]
        assert jinja2.meta.find_undeclared_variables(env.parse(source)) == set(ctx), name
    assert env.undefined is jinja2.StrictUndefined and env.keep_trailing_newline


def test_c_compiles_with_strict_warnings(tmp_path):
    cc = shutil.which("cc")
    assert cc is not None, "hpgen's C backend needs a C compiler named cc on PATH"
    (tmp_path / "kernels.c").write_text(emitted()[1].file("kernels.c"))
    proc = subprocess.run([cc] + STRICT_FLAGS + include_flags()
                          + ["-o", str(tmp_path / "k.so"), str(tmp_path / "kernels.c")],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr == ""


@pytest.mark.parametrize("backend", ["c", "python"])
def test_kernels_agree_with_casadi(backend):
    step, _ = emitted()
    it = integrator(backend)
    rng = np.random.default_rng(1)
    for k in step.kernels:
        for _ in range(5):
            args = _random_args(k.function, rng)
            ref = _casadi_eval(k.function, args)
            got = it.kernel(k.name, *args)
            assert len(got) == len(ref)
            for r, g in zip(ref, got):
                assert g.dtype == np.float64 and g.shape == r.shape
                np.testing.assert_allclose(g, r, rtol=1e-13, atol=1e-300, err_msg=k.name)


def test_c_and_python_kernels_are_bitwise_equal():
    step, _ = emitted()
    rng = np.random.default_rng(2)
    for k in step.kernels:
        args = _random_args(k.function, rng)
        for a, b in zip(integrator("c").kernel(k.name, *args),
                        integrator("python").kernel(k.name, *args)):
            assert np.array_equal(a, b), k.name


def _all_ops_function():
    x = ca.SX.sym("x", 2)
    a, b = x[0], x[1]
    ops = [a + b, a - b, a * b, a / b, -a, ca.exp(a), ca.log(a), a ** b, a ** 2.5, a ** 3,
           ca.sqrt(a), 2 * a, ca.sin(a), ca.cos(a), ca.tan(a), ca.asin(a), ca.acos(a),
           ca.atan(a), a < b, a <= b, a == b, a != b, ca.logic_not(a), ca.logic_and(a, b),
           ca.logic_or(a, b), ca.floor(a), ca.ceil(a), ca.fmod(a, b), ca.fabs(a), ca.sign(a),
           ca.copysign(a, b), ca.if_else(a > 0, b / a, a * b), ca.erf(a), ca.fmin(a, b),
           ca.fmax(a, b), 1 / a, ca.sinh(a), ca.cosh(a), ca.tanh(a), ca.asinh(a),
           ca.acosh(a), ca.atanh(a), ca.atan2(a, b), ca.log1p(a), ca.expm1(a),
           ca.hypot(a, b), ca.remainder(a, b), a + ca.inf, a * math.nan, ca.exp(1000 * a)]
    return ca.Function("allops", [x], [ca.vertcat(*ops)], ["x"], ["y"])


def _python_kernel(kernel):
    """Compile one kernel's printed lines with the helpers of the generated kernels.py."""
    ns = {}
    exec(compile(emitted()[1].file("kernels.py"), "kernels.py", "exec"), ns)
    f = kernel.function
    body = "\n".join("    " + line for line in kernel_lines(kernel))
    src = (f"def k(x):\n    x = _vec(x, {f.numel_in(0)}, 'x')\n"
           f"    r0 = [0.0] * {f.numel_out(0)}\n{body}\n    return r0\n")
    exec(compile(src, "allops", "exec"), ns)
    return ns["k"]


def test_python_printer_covers_scalar_ops_with_c_semantics():
    f = _all_ops_function()
    ops = {f.instruction_id(k) for k in range(f.n_instructions())}
    # CasADi 3.6.0 records 2 * a as OP_MUL, later releases as OP_TWICE
    x = ca.SX.sym("x")
    twice = ca.Function("twice", [x], [2 * x])
    emits_twice = ca.OP_TWICE in {twice.instruction_id(k) for k in range(twice.n_instructions())}
    assert {ca.OP_IF_ELSE_ZERO, ca.OP_CONSTPOW, ca.OP_POW, ca.OP_SQ, ca.OP_INV, ca.OP_FMIN,
            ca.OP_SIGN, ca.OP_COPYSIGN, ca.OP_ATAN2, ca.OP_HYPOT} <= ops
    assert (ca.OP_TWICE in ops) == emits_twice
    k = _python_kernel(Kernel("allops", f, ("x",), ("y",)))
    points = [(0.5, 0.25), (-0.5, 2.0), (0.0, 0.0), (-0.0, -3.0), (2.0, -0.0), (1.0, 1.0),
              (-1.0, 0.5), (math.inf, 1.0), (-math.inf, 2.0), (math.nan, 1.0), (3.7, -2.2),
              (1e300, 1e-300)]
    for pt in points:
        with np.errstate(all="ignore"):
            ref = np.array(f(ca.DM(pt)).full()).ravel()
        got = np.array(k(pt))
        np.testing.assert_allclose(got, ref, rtol=1e-15, atol=0, equal_nan=True,
                                   err_msg=str(pt))
        assert np.array_equal(np.signbit(got[ref == 0]), np.signbit(ref[ref == 0])), pt


def test_unsupported_op_raises_codegen_error():
    x = ca.SX.sym("x", 1)
    f = ca.Function("bad", [x], [ca.erfinv(x)], ["x"], ["y"])
    with pytest.raises(CodegenError, match="ERFINV"):
        kernel_lines(Kernel("bad", f, ("x",), ("y",)))
    step = toy_step()
    g = ca.SX.sym("g", 9)
    kernels = tuple(Kernel(k.name, ca.Function("defect", [g], [ca.erfinv(g[0])]), ("g",),
                           ("e",)) if k.name == "defect" else k for k in step.kernels)
    bad = DiscreteStep(**{**step.__dict__, "kernels": kernels})
    with pytest.raises(CodegenError, match="erfinv"):
        emit(bad, toy_info())


def test_contract_violations_are_reported():
    step = toy_step()
    z = ca.SX.sym("z", 2)
    kernels = tuple(Kernel("margin", ca.Function("margin", [z, ca.SX.sym("h")], [z[0]]),
                           ("z", "h"), ("m",)) if k.name == "margin" else k
                    for k in step.kernels)
    with pytest.raises(CodegenError, match="margin: input 0"):
        emit(DiscreteStep(**{**step.__dict__, "kernels": kernels}), toy_info())
    with pytest.raises(CodegenError, match="kernels must be"):
        emit(DiscreteStep(**{**step.__dict__, "kernels": step.kernels[:-1]}), toy_info())


def test_generated_dir_layout():
    d = module_dir()
    assert sorted(p.name for p in d.iterdir() if not p.name.startswith(("_kernels", "."))) == \
        ["__init__.py", "kernels.c", "kernels.py", "meta.json", "model.yaml"]

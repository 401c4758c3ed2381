"""Generated code does not depend on what the process derived before: a family module's
kernels.c built twice in one process, around other builds, is byte for byte the same; the
mapped calls of one function share one wrapper however many other functions were mapped."""
from __future__ import annotations

import casadi as ca

import hpgen.api as api
from hpgen.derive.family_map import mapped
from tests.conftest import EXAMPLES

SIG = "(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {"


def _kernels_c(name: str) -> str:
    path = EXAMPLES / f"{name}.yaml"
    files = api.generate_files(str(path), path.read_text(),
                               api.CompileOptions(backend="c"), "0" * 16)
    return files["kernels.c"]


def _live_mapped_functions(count: int) -> list:
    """``count`` distinct functions, each mapped once and kept alive (the state a long
    session of derivations leaves behind)."""
    x = ca.SX.sym("x", 2)
    keep = [ca.Function(f"other{k}", [x], [x * (k + 1)]) for k in range(count)]
    for f in keep:
        mapped(f, 2)
    return keep


def _two_calls_code(between) -> str:
    """C code of the Jacobian of two mapped calls of one function, ``between()`` run
    between the two calls."""
    x = ca.SX.sym("x", 3)
    f = ca.Function("f", [x], [ca.sin(x) * x[0]], {"never_inline": True, "jac_penalty": 0})
    X = ca.MX.sym("X", 3, 2)
    a = mapped(f, 2)(X)
    kept = between()
    b = mapped(f, 2)(X)
    del kept
    J = ca.Function("J", [X], [ca.jacobian(ca.vec(a * b), ca.vec(X))])
    gen = ca.CodeGenerator("j.c")
    gen.add(J)
    return gen.dump()


def test_mapped_calls_of_one_function_share_their_wrapper_after_many_others():
    alone = _two_calls_code(lambda: None)
    assert _two_calls_code(lambda: _live_mapped_functions(300)) == alone


def test_a_family_module_is_byte_identical_when_built_again_after_other_builds():
    first = _kernels_c("pendulum_chain")
    keep = _live_mapped_functions(300)
    for other in ("double_body_chain", "four_bar"):
        _kernels_c(other)
    again = _kernels_c("pendulum_chain")
    del keep
    assert again.count(SIG) == first.count(SIG)
    assert again == first

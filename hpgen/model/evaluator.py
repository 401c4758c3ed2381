"""The whitelist evaluator: a checked ``ast`` tree (hpgen.model.syntax.parse_checked) -> sympy.

Used by the front ends in hpgen.model.expr (the Lagrangian, the scene's section and recorded
expressions); see there for the grammar, the names and the limits. Nothing here evaluates
strings: ``_Evaluator.walk`` interprets the whitelisted node types only.

Values are sympy scalars or numpy object arrays (1-D vectors, 2-D matrices) of sympy scalars;
``+ - * /`` are elementwise with scalar broadcasting, ``**`` needs a scalar exponent. Literal ints
stay exact; parameters are numbers (int -> Integer, float -> Float with the exact binary value).
Every elementwise operation is charged against MAX_WORK; constants must be finite reals within
double range (exact rationals within MAX_EXACT_BITS bits).
"""
from __future__ import annotations

import ast
import functools
import math
import re

import numpy as np
import sympy as sp

from ..errors import ModelError
from . import bodies
from .bodies import BodyIndexed
from .families import family_of
from .syntax import fail
from .values import _as_sympy, _shape, _shape_text, _symbols, _to_array

MAX_WORK = 50_000
MAX_EXACT_BITS = 4096

FUNCTIONS = {"sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "exp": sp.exp, "log": sp.log,
             "sqrt": sp.sqrt, "dot": None, "cross": None, "transpose": None, "norm2": None,
             "sum": None}
MAX_SUM_TERMS = 10_000
MAX_INDEX = 10**9
_FACTOR_ALIAS = re.compile(r"(R|x)_([0-9]+)")
_NONFINITE = (sp.S.NaN, sp.S.ComplexInfinity, sp.S.Infinity, sp.S.NegativeInfinity)


@functools.lru_cache(maxsize=8)
def _group_names(group, variables: tuple):
    """(vars, g, names, varying entries of g, factor layouts, family, body names) of the
    evaluators on ``group`` with the algebra-length ``variables``: built once per group (a
    family's g has n*n entries); the arrays are read-only, so evaluators share them."""
    from ..groups import group_from_spec
    n, d = group.n, group.d
    vars_ = {v: _symbols(v, d) for v in variables}
    g = _symbols("g", n, n)
    names = {**vars_, "g": g, "pi": sp.pi}
    factors = group.factors
    product = len(factors) > 1
    varying = set()                     # entries of g that vary on the group
    for k, lay in enumerate(factors):
        fg = group_from_spec(lay.name) if product else group
        blk = g[lay.row:lay.row + lay.n, lay.row:lay.row + lay.n]
        sfx = f"_{k}" if product else ""
        if product:
            for v, arr in vars_.items():
                names[v + sfx] = arr[lay.off:lay.off + lay.d]
            names["g" + sfx] = blk
        if fg.rotation_block:
            a, b = fg.rotation_block
            names["R" + sfx] = blk[a:b, a:b]
            varying.update(blk[a:b, a:b].flat)
        if fg.translation_block:
            a, b = fg.translation_block
            names["x" + sfx] = blk[a:b, lay.n - 1]
            varying.update(blk[a:b, lay.n - 1].flat)
    family = family_of(group)
    body: dict = {}
    if family is not None:
        fgroups = [group_from_spec(lay.name) for lay in factors]
        body = bodies.body_names(factors, fgroups, vars_, g)
        names.update(body)
    return vars_, g, names, frozenset(varying), factors, family, body


class _Evaluator:
    """Evaluates a checked tree. ``variables``: the algebra-length vectors the expression may use
    (("xi",) for the Lagrangian, ("mu",) for the section, ("xi", "mu") for a recorded
    expression), symbols ``<name>_k`` (real), with ``<name>_k`` factor slices for products. ``forbidden``: (regex, message) for names refused with a
    dedicated message (the section's xi). ``extra``: further names and their sympy values
    (the time t, the control inputs of a force). ``refused``: {name: message} for names
    that exist in the model but not in this expression (an input in the Lagrangian)."""

    def __init__(self, group, parameters: dict, variables=("xi",), forbidden=None,
                 extra=None, refused=None):
        self.vars, self.g, names, varying, self.layouts, self.family, body = \
            _group_names(group, tuple(variables))
        self.params, self.cache, self.work = parameters, {}, 0
        self.forbidden = forbidden
        self.refused = dict(refused or {})
        self.product = len(self.layouts) > 1
        if self.family is not None:
            clash = sorted(set(body) & set(parameters))
            if clash:
                raise ModelError(f"the parameter {clash[0]!r} has the name of a body-indexed "
                                 f"name of a family model ({', '.join(sorted(body))}); rename "
                                 "the parameter", field="lagrangian")
        names = dict(names)
        names.update(extra or {})
        self.names, self.varying_g = names, varying
        self.bound: dict = {}              # sum variables in scope -> their current int value

    # ---- helpers ---------------------------------------------------------------------------
    def charge(self, node, amount: int):
        self.work += amount
        if self.work > MAX_WORK:
            raise fail(node, f"expression too large: more than {MAX_WORK} elementwise operations "
                             f"(limit {MAX_WORK})")

    def checked(self, node, v):
        """Reject a constant scalar that is not a finite real number within double range."""
        if isinstance(v, np.ndarray):
            for e in v.flat:
                self.checked(node, e)
            return v
        if v.is_Atom and v.is_number:
            if v in _NONFINITE or v is sp.S.NaN:
                raise fail(node, f"the value is not finite ({v}; a division by zero?)")
            try:
                f = float(v)
            except (TypeError, ValueError):
                raise fail(node, f"the constant {v} is not a real number") from None
            except OverflowError:
                f = math.inf
            if not math.isfinite(f):
                raise fail(node, "a constant is not finite or exceeds double precision range")
            if v.is_Rational and max(int(v.p).bit_length(), int(v.q).bit_length()) > MAX_EXACT_BITS:
                raise fail(node, f"exact number too large (limit {MAX_EXACT_BITS} bits)")
        return v

    def elementwise(self, node, fn, values, what):
        shapes = {_shape(v) for v in values} - {()}
        if not shapes:
            self.charge(node, len(values))
            return self.checked(node, fn(*values))
        if len(shapes) > 1:
            desc = " and ".join(_shape_text(s) for s in sorted(shapes, key=len))
            raise fail(node, f"{what}: shapes do not match ({desc}); use dot(...) for products")
        shape = shapes.pop()
        size = int(np.prod(shape))
        self.charge(node, size * len(values))
        out = [fn(*[v.flat[i] if isinstance(v, np.ndarray) else v for v in values])
               for i in range(size)]
        return self.checked(node, _to_array(out, shape))

    # ---- evaluation ------------------------------------------------------------------------
    def walk(self, node):
        try:
            if isinstance(node, ast.BinOp):
                return self.binop(node)
            if isinstance(node, ast.UnaryOp):
                v = self.walk(node.operand)
                if isinstance(node.op, ast.UAdd):
                    return v
                return self.elementwise(node, lambda a: -a, [v], "unary -")
            if isinstance(node, ast.Constant):
                return self.constant(node)
            if isinstance(node, ast.Name):
                return self.name(node)
            if isinstance(node, ast.Subscript):
                return self.subscript(node)
            if isinstance(node, ast.Call):
                return self.call(node)
        except (TypeError, ValueError, AttributeError, ZeroDivisionError) as e:
            if isinstance(e, ModelError):
                raise
            raise fail(node, f"cannot evaluate this expression ({type(e).__name__}: "
                             f"{str(e).splitlines()[0][:80] if str(e) else ''})") from None
        raise fail(node, f"{type(node).__name__} is not allowed", allowed=True)

    def binop(self, node):
        op = type(node.op)
        if op is ast.Pow:
            base, expo = self.walk(node.left), self.walk(node.right)
            if _shape(expo):
                raise fail(node, f"the exponent of ** must be a scalar, got a "
                                 f"{_shape_text(_shape(expo))}")
            if expo.is_Rational and not expo.is_Integer:
                big = abs(expo.p) // expo.q + 1
            else:
                big = abs(int(expo)) if expo.is_Integer else 0
            for b in (base.flat if isinstance(base, np.ndarray) else [base]):
                if b.is_Rational and big and b not in (0, 1, -1):
                    bits = max(int(b.p).bit_length(), int(b.q).bit_length())
                    if big * bits > MAX_EXACT_BITS:
                        raise fail(node, f"exact power too large (limit {MAX_EXACT_BITS} bits); "
                                         "write the base as a float")
            return self.elementwise(node, lambda a, b: a ** b, [base, expo], "**")
        if op is ast.MatMult:
            return self.dot(node, self.walk(node.left), self.walk(node.right))
        # flatten a left-nested chain of + - (or * /) iteratively
        kinds = (ast.Add, ast.Sub) if op in (ast.Add, ast.Sub) else (ast.Mult, ast.Div)
        chain, cur = [], node
        while isinstance(cur, ast.BinOp) and isinstance(cur.op, kinds):
            chain.append((type(cur.op), cur.right))
            cur = cur.left
        operands = [self.walk(cur)]
        signs = [True]
        for opk, right in reversed(chain):
            v = self.walk(right)
            if opk is ast.Div:
                v = self.elementwise(right, lambda a: sp.Integer(1) / a, [v], "/")
            operands.append(v)
            signs.append(opk is not ast.Sub)
        if kinds[0] is ast.Add:
            def fn(*vals):
                return sp.Add(*[a if s else -a for a, s in zip(vals, signs)])
            return self.elementwise(node, fn, operands, "+/-")
        return self.elementwise(node, lambda *vals: sp.Mul(*vals), operands, "*//")

    def constant(self, node):
        v = node.value
        if type(v) is int:
            if v.bit_length() > 1024:
                raise fail(node, "integer literal too large (exceeds double precision range)")
            return sp.Integer(v)
        if type(v) is float:
            if not math.isfinite(v):
                raise fail(node, f"number literal {v} is not finite")
            return sp.Float(v)
        raise fail(node, f"{type(v).__name__} constant is not allowed", allowed=True)

    def name(self, node):
        v = self.lookup(node)
        if isinstance(v, BodyIndexed):
            raise fail(node, f"{v.name} is indexed by body in a family model: write "
                             f"{v.name}[i] for body i's {v.what}"
                             + (f", {v.name}[i][k] for its component k" if v.name == "xi" else ""))
        return v

    def lookup(self, node):
        """The value of a name (a BodyIndexed for a family's body-indexed names)."""
        nm = node.id
        if nm in self.bound:
            return sp.Integer(self.bound[nm])
        if nm in self.names:
            return self.names[nm]
        if self.forbidden and self.forbidden[0].fullmatch(nm):
            raise fail(node, self.forbidden[1])
        if nm in self.refused:
            raise fail(node, self.refused[nm])
        if nm in self.params:
            if nm not in self.cache:
                self.cache[nm] = self.checked(node, _as_sympy(self.params[nm]))
            return self.cache[nm]
        if nm in FUNCTIONS:
            raise fail(node, f"{nm} is a function; call it as {nm}(...)")
        if self.product and nm in ("R", "x"):
            avail = sorted(k for k in self.names if k.startswith(nm + "_"))
            raise fail(node, f"{nm} is not defined for a product group; use the per-factor "
                             f"names ({', '.join(avail) or 'no factor has one'})")
        fac = _FACTOR_ALIAS.fullmatch(nm) if self.product else None
        if fac and int(fac.group(2)) < len(self.layouts):
            k = int(fac.group(2))
            raise fail(node, f"{nm} is not defined: factor {k} ({self.layouts[k].name}) has no "
                             f"{'rotation block' if fac.group(1) == 'R' else 'translation'}")
        if nm in ("R", "x"):
            raise fail(node, f"{nm} is not defined for this group "
                             f"({'no rotation block' if nm == 'R' else 'no translation'})")
        avail = sorted(self.names) + sorted(self.params)
        raise fail(node, f"unknown name {nm!r}; available names: {', '.join(avail)}")

    def subscript(self, node):
        base = node.value
        val = self.lookup(base) if isinstance(base, ast.Name) else self.walk(base)
        sl = node.slice
        idx_nodes = sl.elts if isinstance(sl, ast.Tuple) else [sl]
        idx = tuple(self.index_value(n) for n in idx_nodes)
        if isinstance(val, BodyIndexed):
            return bodies.select_body(node, val, idx)
        if isinstance(base, ast.Name) and base.id in self.params and self.family is not None \
                and any(self.uses_sum_variable(n) for n in idx_nodes):
            return bodies.body_parameter(node, base.id, val, idx, self.family.count)
        shape = _shape(val)
        if len(idx) != len(shape):
            want = {0: "a scalar cannot be indexed", 1: "index a vector with one index v[i]",
                    2: "index a matrix with two indices M[i, j]"}[len(shape)]
            raise fail(node, f"wrong number of indices for a {_shape_text(shape)}: {want}")
        for i, s in zip(idx, shape):
            if not 0 <= i < s:
                raise fail(node, f"index {list(idx)} out of range for a {_shape_text(shape)}")
        return val[idx]

    # ---- families of bodies (hpgen.model.families) -------------------------------------------
    def index_value(self, node) -> int:
        """An index as a Python int: literals, sum variables, integer parameters, + - *."""
        if isinstance(node, ast.Constant) and type(node.value) is int:
            return node.value
        if isinstance(node, ast.Name):
            nm = node.id
            if nm in self.bound:
                return self.bound[nm]
            value = self.params.get(nm)
            if type(value) is int:
                return value
            what = ("a runtime parameter" if isinstance(value, (sp.Basic, np.ndarray))
                    else "not an integer parameter" if nm in self.params
                    else "not a sum variable or a parameter")
            raise fail(node, f"the index {nm!r} is {what}: indices must be non-negative integer "
                             "literals or integer expressions of sum variables and integer "
                             "parameters")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = self.index_value(node.operand)
            return -v if isinstance(node.op, ast.USub) else v
        if not (isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub, ast.Mult))):
            raise fail(node, "expected an integer: a literal, a sum variable, an integer "
                             "parameter, or + - * of them")
        a, b = self.index_value(node.left), self.index_value(node.right)
        v = a + b if isinstance(node.op, ast.Add) else a - b if isinstance(node.op, ast.Sub) \
            else a * b
        if abs(v) > MAX_INDEX:
            raise fail(node, f"index expression too large ({v})")
        return v

    def uses_sum_variable(self, node) -> bool:
        return any(isinstance(n, ast.Name) and n.id in self.bound for n in ast.walk(node))

    def sum(self, node):
        args = node.args
        if len(args) not in (2, 4) or not isinstance(args[0], ast.Name):
            raise fail(node, "sum takes (i, term) over the bodies 0..N-1 or (i, start, stop, "
                             "term) over start..stop-1, with i a new name")
        var = args[0].id
        if var in self.names or var in self.params or var in self.bound or var in FUNCTIONS \
                or var in self.refused or (self.forbidden and self.forbidden[0].fullmatch(var)):
            raise fail(args[0], f"the sum variable {var!r} shadows a name of the model; choose "
                                "a new name, e.g. i or j")
        if len(args) == 2:
            if self.family is None:
                raise fail(node, "sum(i, term) sums over the bodies of a family (group G^N); "
                                 "give the range otherwise: sum(i, start, stop, term)")
            start, stop = 0, self.family.count
        else:
            start, stop = self.index_value(args[1]), self.index_value(args[2])
        if stop - start > MAX_SUM_TERMS:
            raise fail(node, f"sum over {stop - start} terms (limit {MAX_SUM_TERMS})")
        terms = []
        for k in range(start, stop):
            self.bound[var] = k
            terms.append(self.walk(args[3 if len(args) == 4 else 1]))
        self.bound.pop(var, None)
        if not terms:
            return sp.Integer(0)
        return self.elementwise(node, lambda *vals: sp.Add(*vals), terms, "sum")

    def call(self, node):
        fname = node.func.id
        if fname == "sum":
            return self.sum(node)
        if fname in ("cross", "transpose", "norm2"):
            return self.vector_function(node, fname)
        if fname == "dot":
            if len(node.args) != 2:
                raise fail(node, f"dot takes 2 arguments, got {len(node.args)}")
            return self.dot(node, self.walk(node.args[0]), self.walk(node.args[1]))
        if len(node.args) != 1:
            raise fail(node, f"{fname} takes 1 argument, got {len(node.args)}")
        return self.elementwise(node, FUNCTIONS[fname], [self.walk(node.args[0])], fname)

    def vector_function(self, node, fname):
        want = 2 if fname == "cross" else 1
        if len(node.args) != want:
            raise fail(node, f"{fname} takes {want} argument{'s' if want > 1 else ''}, got "
                             f"{len(node.args)}")
        vals = [self.walk(a) for a in node.args]
        shapes = [_shape(v) for v in vals]
        if fname == "cross" and shapes != [(3,), (3,)]:
            raise fail(node, "cross: expected two vectors of length 3, got a "
                             + " and a ".join(_shape_text(s) for s in shapes))
        if fname == "transpose" and len(shapes[0]) != 2:
            raise fail(node, f"transpose: expected a matrix, got a {_shape_text(shapes[0])}")
        if fname == "norm2" and not shapes[0]:
            raise fail(node, "norm2: expected a vector or a matrix, got a scalar")
        self.charge(node, 3 * max(1, int(np.prod(shapes[0]))))
        return self.checked(node, getattr(bodies, fname)(*vals))

    def dot(self, node, a, b):
        sa, sb = _shape(a), _shape(b)
        if not sa or not sb or sa[-1] != sb[0]:
            raise fail(node, f"dot: shapes do not match ({_shape_text(sa)} and "
                             f"{_shape_text(sb)}); inner dimensions must agree")
        A = a if len(sa) == 2 else a.reshape(1, -1)
        B = b if len(sb) == 2 else b.reshape(-1, 1)
        m, k, n = A.shape[0], A.shape[1], B.shape[1]
        self.charge(node, m * k * n)
        out = [sp.Add(*[A[i, t] * B[t, j] for t in range(k)]) for i in range(m) for j in range(n)]
        res = _to_array(out, (m, n))
        shape = sa[:-1] + sb[1:]
        return self.checked(node, res.reshape(shape) if shape else res[0, 0])

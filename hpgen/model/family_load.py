"""Loading a family model without expanding its Lagrangian: when every top-level sum of a
model on G^N is local to its body (hpgen.model.bodyterms), the sums are evaluated once for a
generic body and the expanded sympy Lagrangian (N copies of each term) is built only when
something asks for Model.lagrangian (the expanded derivation, analyses); the per-body
derivation never does.

The fast path is taken only when the full parse would accept the text: any failure here
(a term that is not local, a name or an index the evaluator refuses, a sum range outside
0..N, a work or tree-size estimate N times a term's above the parser's limits) falls back to
the full parse, which then reports the one-line error as always.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class BodyLagrangian:
    """The Lagrangian as the sum of its BodyTerms (hpgen.model.bodyterms) over their ranges,
    without its joint potentials (configuration only: no part of d2l/dxi2, all that the
    loader's checks and the projection read); ``data``: {body data symbol: per-body runtime
    symbols}."""
    terms: tuple
    data: dict


def _sum_headers_ok(group, tree, lag_params: dict, refused: dict) -> bool:
    """The full evaluator's checks of every top-level sum's header (arity, a new variable
    name, the number of terms), without evaluating the terms."""
    import ast

    from .evaluator import FUNCTIONS, MAX_SUM_TERMS, _Evaluator
    from .families import _is_sum
    from .symbols import TIME_SYMBOL
    ev = _Evaluator(group, lag_params, extra={"t": TIME_SYMBOL}, refused=refused)
    stack = [tree.body]
    while stack:
        node = stack.pop()
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
            stack += [node.left, node.right]
            continue
        if not _is_sum(node):
            return False
        args = node.args
        if len(args) not in (2, 4) or not isinstance(args[0], ast.Name) or node.keywords:
            return False
        var = args[0].id
        if var in ev.names or var in lag_params or var in FUNCTIONS or var in refused:
            return False
        if len(args) == 4 and ev.index_value(args[2]) - ev.index_value(args[1]) > MAX_SUM_TERMS:
            return False
    return True


def local_lagrangian(group, text, exact: dict, lag_params: dict, refused: dict):
    """(family with its sums, BodyLagrangian, xi_symbols, g_symbols) when the family's
    Lagrangian can stay unexpanded, else None; ``exact``: the parameters as written, ``lag_params``: as the
    Lagrangian's evaluator takes them (runtime ones as symbols)."""
    from .bodyterms import _body_term, _NotLocal, _potential
    from .evaluator import MAX_WORK, _group_names
    from .expr import MAX_TREE, _final_checks
    from .families import family_of, with_sums
    from .syntax import parse_checked
    from .values import symbol_rows
    if family_of(group) is None or not isinstance(text, str):
        return None
    try:                    # any failure: the full parse decides (and words the refusal)
        tree = parse_checked(text)
        if not _sum_headers_ok(group, tree, lag_params, refused):
            return None
        family = with_sums(family_of(group), text, tree, exact)
        if family.rest is not None or not family.sums:
            return None
        work, data, depends, size, terms = [], {}, False, 0, []
        for s in family.sums:
            if not 0 <= s.start <= s.stop <= family.count:
                return None
            try:
                term = _body_term(family, s, lag_params, data, work)
            except _NotLocal:      # a joint potential: no xi, so no part of d2l/dxi2
                expr = _potential(family, s, lag_params, work).expr
                _final_checks(expr, ())
                size += (s.stop - s.start) * _tree_size(expr)
                continue
            terms.append(term)
            xis = [x for x in term.expr.free_symbols if str(x).startswith("xi_")]
            depends = _final_checks(term.expr, xis) or depends
            size += (s.stop - s.start) * _tree_size(term.expr)
        count = sum(w * (s.stop - s.start) for w, s in zip(work, family.sums))
        if not depends or count > MAX_WORK or size > MAX_TREE:
            return None
    except Exception:       # noqa: BLE001 (re-raised, located, by the full parse)
        return None
    xi = _group_names(group, ("xi",))[0]["xi"]
    return (family, BodyLagrangian(tuple(terms), data), tuple(xi.tolist()),
            symbol_rows("g", group.n, group.n))


def body_terms_hessian(lag: BodyLagrangian, group, g, runtime: dict):
    """d2l/dxi2 (d x d) of the BodyLagrangian ``lag`` at numeric g (n x n) and xi = 0,
    t = 0, runtime parameters (and body data) at their defaults ``runtime``."""
    import casadi as ca
    import numpy as np
    X = ca.SX.sym("xi", group.d)
    total = body_terms_sx(lag, group, X, lambda r, c: ca.SX(float(g[r][c])), runtime)
    fun = ca.Function("legendre_map", [X], [ca.hessian(total, X)[0]])
    return np.array(fun(np.zeros(group.d)), dtype=float)


def body_terms_sx(lag: BodyLagrangian, group, X, entry, runtime: dict):
    """The BodyLagrangian ``lag`` as a casadi SX at t = 0: xi = X (d), g's entry (r, c) =
    ``entry(r, c)``, runtime parameters (and body data) at ``runtime``."""
    import casadi as ca

    from ..derive.lagrangian import to_casadi
    from ..groups import group_from_spec
    from .symbols import TIME_SYMBOL
    body = group_from_spec(group.family.body)
    nb, db = body.n, body.d
    data = lag.data
    total = ca.SX(0)
    for t in lag.terms:
        for k in range(t.start, t.stop):
            mapping = {TIME_SYMBOL: ca.SX(0), t.index: ca.SX(k)}
            for s in t.expr.free_symbols:
                name = str(s)
                if name.startswith("xi_"):
                    mapping[s] = X[k * db + int(name[3:])]
                elif name.startswith("g_"):
                    a, b = map(int, name[2:].split("_"))
                    mapping[s] = entry(k * nb + a, k * nb + b)
                elif s in runtime:
                    mapping[s] = ca.SX(runtime[s])
                elif name.startswith("body:"):
                    mapping[s] = ca.SX(runtime[data[s][k]])
            total = total + to_casadi(t.expr, mapping)
    return total


def _tree_size(expr) -> int:
    """The number of nodes of ``expr`` as a tree (shared subtrees counted every time)."""
    size, memo, stack = 0, {}, [(expr, False)]
    while stack:
        e, done = stack.pop()
        if done:
            memo[e] = 1 + sum(memo[a] for a in e.args)
            continue
        if e in memo:
            continue
        stack.append((e, True))
        stack.extend((a, False) for a in e.args if a not in memo)
    size = memo[expr]
    return size

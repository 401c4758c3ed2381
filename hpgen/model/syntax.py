"""Lagrangian text -> a checked Python ``ast`` tree (nothing is ever evaluated here).

``parse_checked(text)`` parses with ``ast.parse(text, mode="eval")`` and checks, without
recursion: size (<= MAX_CHARS characters, <= MAX_NODES expression nodes, i.e. names, constants,
operations, calls, subscripts; operator and context markers are not counted), the whitelist of
node types (see ALLOWED; an index is a non-negative integer literal or an integer expression
``+ - *`` of names, whose value the evaluator checks) and the nesting depth (<= MAX_DEPTH, where a left-nested chain of ``+ -`` or of
``* /`` counts as one level). CPython builds left-nested chains recursively, so ast.parse runs
with a temporarily raised recursion limit (enough for any chain within MAX_NODES); if it still
fails, a top-level sum is split at its binary ``+``/``-`` tokens and the terms parsed one by one.
Errors are ModelError(field="lagrangian") naming the construct and its column; when several
constructs are not allowed, a dunder name or attribute (``__import__``, ``.__class__``) is
reported first, then the leftmost one.
"""
from __future__ import annotations

import ast
import io
import sys
import tokenize
import warnings

from ..errors import ModelError

MAX_CHARS = 200_000
MAX_NODES = 50_000
MAX_DEPTH = 200
FUNCTION_NAMES = ("sin", "cos", "tan", "exp", "log", "sqrt", "dot", "cross", "transpose",
                  "norm2", "sum")
ALLOWED = ("allowed: numbers, names, + - * / ** @, unary -, indexing v[i] and M[i, j] with "
           "integer literals or integer expressions of sum variables, calls of "
           + " ".join(FUNCTION_NAMES))
_BINOPS = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow, ast.MatMult)
_INDEX_OPS = (ast.Add, ast.Sub, ast.Mult)
_OPS = {ast.Mod: "%", ast.FloorDiv: "//", ast.MatMult: "@", ast.BitAnd: "&", ast.BitOr: "|",
        ast.BitXor: "^", ast.LShift: "<<", ast.RShift: ">>", ast.Not: "not", ast.Invert: "~"}
_CONSTRUCTS = {
    ast.Attribute: "attribute access", ast.Lambda: "lambda", ast.ListComp: "list comprehension",
    ast.SetComp: "set comprehension", ast.DictComp: "dict comprehension",
    ast.GeneratorExp: "generator expression", ast.IfExp: "conditional expression",
    ast.Compare: "comparison", ast.BoolOp: "boolean operator", ast.NamedExpr: "assignment (:=)",
    ast.Starred: "starred argument", ast.JoinedStr: "f-string", ast.FormattedValue: "f-string",
    ast.List: "list", ast.Tuple: "tuple", ast.Dict: "dict", ast.Set: "set",
    ast.Slice: "slice", ast.Await: "await", ast.Yield: "yield", ast.YieldFrom: "yield",
}


def where(node) -> str:
    line = getattr(node, "lineno", 1) or 1
    col = (getattr(node, "col_offset", 0) or 0) + 1
    return f"(line {line}, column {col})" if line > 1 else f"(column {col})"


def fail(node, message: str, allowed: bool = False) -> ModelError:
    """ModelError(field="lagrangian") locating ``node``; ``expr_line`` is its expression line."""
    err = ModelError(f"{message} {where(node)}" + (f"; {ALLOWED}" if allowed else ""),
                     field="lagrangian")
    err.expr_line = getattr(node, "lineno", None)
    return err


def _too_large(what: str) -> ModelError:
    return ModelError(f"expression too large: {what}", field="lagrangian")


def _parse(text: str):
    """ast.parse with the recursion limit raised enough for left chains of ~33,000 operators."""
    depth, f = 0, sys._getframe()
    while f is not None:
        depth, f = depth + 1, f.f_back
    old = sys.getrecursionlimit()
    sys.setrecursionlimit(max(old, depth + 11_000))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")         # e.g. SyntaxWarning: invalid decimal literal
            return ast.parse(text, mode="eval")
    finally:
        sys.setrecursionlimit(old)


def _split_sum(text: str):
    """Parse a long top-level sum term by term; None when that is not possible."""
    try:
        toks = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError, ValueError):
        return None
    starts = [0]
    for line in text.splitlines(keepends=True):
        starts.append(starts[-1] + len(line))
    level, prev, cuts = 0, None, []          # cuts: (offset, op, row, col) of binary + -
    for t in toks:
        if t.type == tokenize.OP and t.string in "([{":
            level += 1
        elif t.type == tokenize.OP and t.string in ")]}":
            level -= 1
        elif t.type == tokenize.OP and t.string in "+-" and level == 0 and prev is not None and (
                prev.type in (tokenize.NAME, tokenize.NUMBER) or prev.string in ")]}"):
            cuts.append((starts[t.start[0] - 1] + t.start[1], t.string))
        if t.type not in (tokenize.NL, tokenize.NEWLINE, tokenize.COMMENT, tokenize.ENDMARKER):
            prev = t
    if not cuts or 2 * len(cuts) > MAX_NODES:
        return None
    body, begin, op = None, 0, None
    for end, nxt in cuts + [(len(text), None)]:
        piece = text[begin:end]
        lead = len(piece) - len(piece.lstrip())
        row = text.count("\n", 0, begin + lead)
        col = begin + lead - (text.rfind("\n", 0, begin + lead) + 1)
        term = _parse(piece.strip()).body
        for node in ast.walk(term):
            if hasattr(node, "lineno"):
                if node.lineno == 1:
                    node.col_offset += col
                node.lineno += row
        body = term if body is None else ast.BinOp(
            left=body, op=ast.Add() if op == "+" else ast.Sub(), right=term,
            lineno=body.lineno, col_offset=body.col_offset)
        begin, op = end + 1, nxt
    return ast.Expression(body=body)


def syntax_tree(text: str):
    if len(text) > MAX_CHARS:
        raise _too_large(f"{len(text)} characters (limit {MAX_CHARS})")
    text = text.strip()
    try:
        return _parse(text)
    except SyntaxError as e:
        at = f"column {e.offset or 1}" + (f", line {e.lineno}" if (e.lineno or 1) > 1 else "")
        if "integer string conversion" in (e.msg or ""):     # a literal of > 4300 digits
            err = ModelError(f"integer literal too large: more than 4300 digits ({at}); it "
                             "exceeds double precision range", field="lagrangian")
        else:
            err = ModelError(f"syntax error: {e.msg} ({at}); {ALLOWED}", field="lagrangian")
        err.expr_line = e.lineno
        raise err from None
    except (RecursionError, MemoryError):
        pass
    except (ValueError, OverflowError) as e:
        raise ModelError(f"cannot parse the expression: {e}", field="lagrangian") from None
    try:
        tree = _split_sum(text)
    except (SyntaxError, RecursionError, MemoryError, ValueError, OverflowError):
        tree = None
    if tree is None:
        raise _too_large(f"nested too deeply or too many terms (limits: depth {MAX_DEPTH}, "
                         f"{MAX_NODES} syntax nodes)")
    return tree


def _is_dunder(name: str) -> bool:
    return name.startswith("__")


def _callee(f) -> str:
    """What a call that is not ``name(...)`` calls, for the error message."""
    if isinstance(f, ast.Attribute):
        return f"the attribute '.{f.attr[:40]}'"
    kind = _CONSTRUCTS.get(type(f), type(f).__name__.lower())
    return ("a " if kind[0] not in "aeiou" else "an ") + kind


def _suspicious(node) -> bool:
    """A dunder name or attribute: reported before any other problem of the expression."""
    return (isinstance(node, ast.Name) and _is_dunder(node.id)) or \
        (isinstance(node, ast.Attribute) and _is_dunder(node.attr))


def _is_index(node) -> bool:
    """A non-negative integer literal, or an expression of names, integer literals, + - *
    and unary - that holds at least one name (its value is checked by the evaluator)."""
    if isinstance(node, ast.Constant):
        return type(node.value) is int and node.value >= 0
    named, stack = False, [node]
    while stack:
        n = stack.pop()
        if isinstance(n, ast.Name):
            named = True
        elif isinstance(n, ast.BinOp) and isinstance(n.op, _INDEX_OPS):
            stack += [n.left, n.right]
        elif isinstance(n, ast.UnaryOp) and isinstance(n.op, (ast.USub, ast.UAdd)):
            stack.append(n.operand)
        elif not (isinstance(n, ast.Constant) and type(n.value) is int):
            return False
    return named


def _disallowed(node, t, allowed_tuples):
    """The message for a node that is not allowed, or None."""
    if t is ast.BinOp:
        if isinstance(node.op, _BINOPS):
            return None
        return f"operator {_OPS.get(type(node.op), type(node.op).__name__)} is not allowed"
    if t is ast.Name:
        if _is_dunder(node.id) or not isinstance(node.ctx, ast.Load):
            return f"name {node.id!r} is not allowed (dunder names are forbidden)"
        return None
    if t is ast.Constant:
        if type(node.value) in (int, float):
            return None
        kind = "string" if isinstance(node.value, str) else type(node.value).__name__
        return f"{kind} constant {str(node.value)[:30]!r} is not allowed"
    if t is ast.Subscript:
        idx = node.slice.elts if isinstance(node.slice, ast.Tuple) else [node.slice]
        if isinstance(node.slice, ast.Tuple):
            allowed_tuples.add(id(node.slice))
        if 1 <= len(idx) <= 2 and all(_is_index(i) for i in idx):
            return None
        return ("indices must be one or two non-negative integer literals, or integer "
                "expressions (+ - *) of sum variables and integer parameters, e.g. xi[0], "
                "R[2, 1] or m[i - 1] (no slices, negative literals or other computed indices)")
    if t is ast.Call:
        f = node.func
        if isinstance(f, ast.Name):
            if f.id not in FUNCTION_NAMES:
                return f"function {f.id!r} is not allowed"
            return "keyword arguments are not allowed" if node.keywords else None
        return (f"this call is not allowed (it calls {_callee(f)}; only the functions "
                f"{' '.join(FUNCTION_NAMES)} can be called, by name)")
    if t is ast.Attribute:
        dunder = "; dunder names are forbidden" if _is_dunder(node.attr) else ""
        return f"attribute access is not allowed ('.{node.attr[:40]}'{dunder})"
    if t is ast.Tuple and id(node) in allowed_tuples:
        return None
    return f"{_CONSTRUCTS.get(t, t.__name__)} is not allowed"


def check_tree(tree) -> None:
    """Node count, whitelist and nesting depth, all without recursion."""
    allowed_tuples, bad, count = set(), [], 0
    for node in ast.walk(tree):
        count += isinstance(node, ast.expr)
        if count > MAX_NODES:
            raise _too_large(f"more than {MAX_NODES} syntax nodes (limit {MAX_NODES})")
        t = type(node)
        if t is ast.Expression or t is ast.UnaryOp and isinstance(node.op, (ast.UAdd, ast.USub)):
            continue
        if not isinstance(node, ast.expr) or not hasattr(node, "lineno"):
            if isinstance(node, (ast.operator, ast.unaryop, ast.expr_context)):
                continue                           # judged with their parent node
            msg = f"{_CONSTRUCTS.get(t, t.__name__)} is not allowed"
        else:
            msg = _disallowed(node, t, allowed_tuples) if t is not ast.UnaryOp else \
                f"operator {_OPS.get(type(node.op), '?')} is not allowed"
        if msg:
            bad.append((not _suspicious(node), getattr(node, "lineno", 10**9),
                        getattr(node, "col_offset", 0), count, node, msg))
    if bad:
        *_, node, msg = min(bad, key=lambda b: b[:4])
        raise fail(node, msg, allowed=True)
    stack = [(tree.body, 1)]
    while stack:
        node, depth = stack.pop()
        if depth > MAX_DEPTH:
            raise fail(node, f"expression too large: nested more than {MAX_DEPTH} levels deep "
                             f"(limit {MAX_DEPTH})")
        if isinstance(node, ast.BinOp) and not isinstance(node.op, (ast.Pow, ast.MatMult)):
            kinds = (ast.Add, ast.Sub) if isinstance(node.op, (ast.Add, ast.Sub)) \
                else (ast.Mult, ast.Div)
            while isinstance(node, ast.BinOp) and isinstance(node.op, kinds):
                stack.append((node.right, depth + 1))
                node = node.left
            stack.append((node, depth + 1))
        else:
            stack.extend((c, depth + 1) for c in ast.iter_child_nodes(node)
                         if isinstance(c, ast.expr))


def parse_checked(text: str):
    """The checked ``ast.Expression`` of the Lagrangian text."""
    tree = syntax_tree(text)
    check_tree(tree)
    return tree

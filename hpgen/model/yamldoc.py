"""YAML text -> a located document: plain Python values plus the line of every key/value path.

Conventions:
- The YAML text is only *composed* (``yaml.compose`` with the SafeLoader) into a node tree; plain
  Python values are built here from the nodes, so every key/value path keeps its line
  (``node.start_mark.line + 1``), duplicate keys are detected and no constructor of PyYAML ever
  runs. Only the standard tags str/int/float/bool/null/seq/map (and timestamps, kept as text) are
  accepted; base-60 numbers are not. Mapping keys are kept as their text (``<<`` is just a key).
- A plain (unquoted) scalar that looks like a decimal float (``1e-3``, which YAML 1.1 resolves as a
  string) is a number; a quoted scalar is always a string. ``.inf``/``.nan`` are numbers that are
  rejected as not finite wherever a number is expected.
- Paths are tuples of keys and list indices, shown as ``scene.initial.xi[2]``.
- Aliases are expanded, but to at most len(text) + 1000 nodes; recursive aliases are rejected.
"""
from __future__ import annotations

import math
import re

import yaml

from ..errors import ModelError

MAX_FILE_BYTES = 2 * 1024 * 1024
MAX_YAML_DEPTH = 64

_PLAIN_FLOAT = re.compile(r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?")
_TAG = "tag:yaml.org,2002:"
_SCALAR_TAGS = {_TAG + t for t in ("str", "int", "float", "bool", "null", "timestamp")}


def fmt_path(path) -> str:
    out = ""
    for p in path:
        out += f"[{p}]" if isinstance(p, int) else (("." if out else "") + str(p))
    return out


def is_number(v) -> bool:
    return type(v) in (int, float)


class Doc:
    """The built document: ``data`` (plain Python values) plus the line of every path."""

    def __init__(self, file: str, data, lines: dict):
        self.file, self.data, self.lines = file, data, lines

    def line(self, path):
        path = tuple(path)
        while path and path not in self.lines:
            path = path[:-1]
        return self.lines.get(path)

    def error(self, path, message: str) -> ModelError:
        return ModelError(message, file=self.file, field=fmt_path(path) or None,
                          line=self.line(path))

    # ---- typed getters, used by the schema and by hpgen.model.scene -----------------------
    def mapping(self, path, value, allowed):
        """value as a dict (None -> {}); unknown keys are errors listing the allowed ones."""
        if value is None:
            return {}
        if not isinstance(value, dict):
            raise self.error(path, f"expected a mapping with keys {', '.join(allowed)}, "
                                   f"got {describe(value)}")
        for k in value:
            if k not in allowed:
                raise self.error(tuple(path) + (k,), f"unknown key {k!r}; allowed keys: "
                                                     f"{', '.join(allowed)}")
        return value

    def number(self, path, v, what="a number"):
        if not is_number(v):
            hint = " (quoted strings are not numbers)" if isinstance(v, str) else ""
            raise self.error(path, f"expected {what}, got {describe(v)}{hint}")
        try:
            f = float(v)
        except OverflowError:
            f = math.inf
        if not math.isfinite(f):
            shown = repr(v) if len(repr(v)) <= 40 else f"{repr(v)[:20]}... ({len(repr(v))} digits)"
            raise self.error(path, f"must be finite (expected {what}), got {shown}")
        return f

    def vector(self, path, v, length=None, what="numbers"):
        if not isinstance(v, list) or not v:
            want = f"a list of {length} {what}" if length else f"a non-empty list of {what}"
            raise self.error(path, f"expected {want}, got {describe(v)}")
        if length is not None and len(v) != length:
            raise self.error(path, f"expected a list of {length} {what}, got {len(v)} entries")
        return tuple(self.number(tuple(path) + (i,), x) for i, x in enumerate(v))

    def matrix(self, path, v, shape=None):
        rows = f"{shape[0]} rows of {shape[1]} numbers" if shape else "rows of numbers"
        if not isinstance(v, list) or not v or not all(isinstance(r, list) for r in v):
            raise self.error(path, f"expected a matrix (a list of {rows}), got {describe(v)}")
        if shape and len(v) != shape[0]:
            raise self.error(path, f"expected a {shape[0]} x {shape[1]} matrix, got {len(v)} rows")
        ncol = shape[1] if shape else len(v[0])
        for i, r in enumerate(v):
            if len(r) != ncol:
                raise self.error(tuple(path) + (i,), f"row {i} has {len(r)} entries, expected "
                                                     f"{ncol} (rows must have equal length)")
        return tuple(self.vector(tuple(path) + (i,), r) for i, r in enumerate(v))


def describe(v) -> str:
    if v is None:
        return "nothing (null)"
    if isinstance(v, bool):
        return f"the boolean {v}"
    if isinstance(v, str):
        return f"the string {v[:40]!r}" + ("..." if len(v) > 40 else "")
    if isinstance(v, list):
        return f"a list of {len(v)} entries"
    if isinstance(v, dict):
        return "a mapping"
    return f"{type(v).__name__} {v!r}"


# ---- YAML -> plain values with lines ------------------------------------------------------------
def _scalar(node):
    tag, val = node.tag, node.value
    if tag not in _SCALAR_TAGS:
        raise ValueError(f"YAML tag {tag!r} is not allowed")
    if tag == _TAG + "null":
        return None
    if tag == _TAG + "bool":
        low = val.lower()
        if low in ("yes", "true", "on"):
            return True
        if low in ("no", "false", "off"):
            return False
        raise ValueError(f"invalid boolean {val[:40]!r}")
    if tag in (_TAG + "int", _TAG + "float"):
        return _yaml_number(val, tag == _TAG + "int")
    if node.style is None and _PLAIN_FLOAT.fullmatch(val):
        return _yaml_number(val, False)
    return val


def _yaml_number(text, integer):
    s = text.replace("_", "").strip()
    if ":" in s:
        raise ValueError(f"base-60 number {text[:40]!r} is not supported")
    if len(s) > 400:
        raise ValueError("number literal too long (limit 400 characters)")
    low = s.lower()
    if not integer:
        if low.lstrip("+-") in (".inf", "inf"):
            return -math.inf if low.startswith("-") else math.inf
        if low in (".nan", "nan"):
            return math.nan
        return float(s)
    sign = -1 if s.startswith("-") else 1
    s = s.lstrip("+-")
    if s.startswith(("0b", "0B")):
        return sign * int(s[2:], 2)
    if s.startswith(("0x", "0X")):
        return sign * int(s[2:], 16)
    if s.startswith(("0o", "0O")):
        return sign * int(s[2:], 8)
    if len(s) > 1 and s.startswith("0"):
        return sign * int(s, 8)
    return sign * int(s)


def compose_document(text: str, file: str) -> Doc:
    """Parse YAML text into a Doc; malformed YAML, tags, duplicates -> ModelError."""
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as e:
        mark = e.problem_mark or e.context_mark
        msg = " ".join(str(x) for x in (e.context, e.problem) if x) or "malformed YAML"
        raise ModelError(f"malformed YAML: {msg}", file=file,
                         line=mark.line + 1 if mark else None) from None
    except yaml.YAMLError as e:
        raise ModelError(f"malformed YAML: {str(e).splitlines()[0] if str(e) else e!r}",
                         file=file) from None
    except RecursionError:
        raise ModelError("malformed YAML: nesting too deep", file=file) from None
    if root is None:
        raise ModelError("the model file is empty; expected a mapping with keys name, group, "
                         "lagrangian", file=file)
    if not isinstance(root, yaml.MappingNode):
        raise ModelError("expected a mapping at the top level (name:, group:, lagrangian:, ...)",
                         file=file, line=root.start_mark.line + 1)
    lines = {(): root.start_mark.line + 1}
    limit = len(text) + 1000            # aliases may not expand the document beyond its size
    budget = [limit]

    def build(node, path, stack):
        budget[0] -= 1
        line = node.start_mark.line + 1
        if budget[0] < 0:
            raise ModelError(f"YAML document too large after expanding aliases (more than "
                             f"{limit} nodes)", file=file, line=line)
        if len(path) > MAX_YAML_DEPTH:
            raise ModelError(f"YAML nesting too deep (limit {MAX_YAML_DEPTH})", file=file,
                             line=line, field=fmt_path(path))
        if id(node) in stack:
            raise ModelError("recursive YAML alias", file=file, line=line, field=fmt_path(path))
        if isinstance(node, yaml.ScalarNode):
            try:
                return _scalar(node)
            except (ValueError, OverflowError) as e:
                raise ModelError(str(e), file=file, line=line,
                                 field=fmt_path(path) or None) from None
        stack = stack | {id(node)}
        if isinstance(node, yaml.SequenceNode):
            if node.tag != _TAG + "seq":
                raise ModelError(f"YAML tag {node.tag!r} is not allowed", file=file, line=line,
                                 field=fmt_path(path) or None)
            out = []
            for i, item in enumerate(node.value):
                lines[path + (i,)] = item.start_mark.line + 1
                out.append(build(item, path + (i,), stack))
            return out
        if node.tag != _TAG + "map":
            raise ModelError(f"YAML tag {node.tag!r} is not allowed", file=file, line=line,
                             field=fmt_path(path) or None)
        out = {}
        for knode, vnode in node.value:
            kline = knode.start_mark.line + 1
            if not isinstance(knode, yaml.ScalarNode) or knode.tag not in _SCALAR_TAGS:
                raise ModelError("mapping keys must be plain names", file=file, line=kline,
                                 field=fmt_path(path) or None)
            key = knode.value
            if key in out:
                raise ModelError(f"duplicate key {key!r} (first given on line "
                                 f"{lines[path + (key,)]})", file=file, line=kline,
                                 field=fmt_path(path + (key,)))
            lines[path + (key,)] = kline
            out[key] = build(vnode, path + (key,), stack)
        return out

    doc = Doc(file, None, lines)
    doc.data = build(root, (), frozenset())
    doc.lagrangian_style = doc.section_style = None
    for knode, vnode in root.value:
        if knode.value == "lagrangian" and isinstance(vnode, yaml.ScalarNode):
            doc.lagrangian_style = vnode.style
        if knode.value == "scene" and isinstance(vnode, yaml.MappingNode):
            for sk, sv in vnode.value:
                if sk.value == "section" and isinstance(sv, yaml.ScalarNode):
                    doc.section_style = sv.style
    return doc



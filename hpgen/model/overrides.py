"""Parameter overrides: ``hpgen run chain.yaml --set N=8`` / ``hpgen.compile(path,
parameters={"N": 8})``.

An override replaces the value of a parameter declared in the file's ``parameters:`` mapping
in the model's *text* (the YAML value node is spliced, comments and layout kept), so that the
overridden text is the model: it is what the loader validates, what the content hash covers
(a changed N is a different module) and what the generated module keeps as model.yaml.
Values are numbers or (nested) lists of numbers, written back in YAML flow style; a value
given as text (the command line's ``N=8``, ``J=[1, 2, 3]``) is read as YAML data, never as
Python. Only a declared parameter can be overridden. Errors are one-line ModelErrors naming
the file and the field ``parameters.<name>``.
"""
from __future__ import annotations

import math
import re

import yaml

from ..errors import ModelError
from .yamldoc import _PLAIN_FLOAT

MAX_VALUE_CHARS = 10_000
#: the text between a key and its own value node: the colon, blanks, an optional anchor
_VALUE_START = re.compile(r"\s*:\s*(&[^\s]+\s*)?")


def parse_assignment(text: str) -> tuple[str, object]:
    """``NAME=VALUE`` (the command line's --set) -> (name, value read as YAML data)."""
    name, sep, value = str(text).partition("=")
    name = name.strip()
    if not sep or not name:
        raise ModelError(f"expected NAME=VALUE, e.g. N=8, got {text!r}", field="option set")
    return name, read_value(value, f"option set {name}")


def read_value(text: str, field: str):
    """A number or a (nested) list of numbers from YAML text (safe loader, plain data)."""
    if len(text) > MAX_VALUE_CHARS:
        raise ModelError(f"the value is too long (limit {MAX_VALUE_CHARS} characters)",
                         field=field)
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        raise ModelError(f"cannot read the value {text.strip()[:40]!r}: expected a number or a "
                         "list of numbers, e.g. 8 or [1.0, 2.0]", field=field) from None
    value = _plain_floats(value)
    _check_value(value, field)
    return value


def _plain_floats(value):
    """YAML 1.1 reads 1e-3 as a string: such strings as floats (hpgen.model.yamldoc's rule)."""
    if isinstance(value, list):
        return [_plain_floats(v) for v in value]
    if isinstance(value, str) and _PLAIN_FLOAT.fullmatch(value.strip()):
        return float(value)
    return value


def _check_value(value, field: str) -> None:
    if isinstance(value, list) and value:
        for v in value:
            _check_value(v, field)
        return
    if type(value) in (int, float) and math.isfinite(value):
        return
    raise ModelError(f"expected a finite number or a non-empty list of numbers, got "
                     f"{str(value)[:40]!r}", field=field)


def _flow(value) -> str:
    if isinstance(value, list):
        return "[" + ", ".join(_flow(v) for v in value) + "]"
    return repr(value) if type(value) is float else str(value)


def apply_overrides(text: str, overrides: dict | None, file: str = "<string>") -> str:
    """``text`` with the parameters in ``overrides`` ({name: value}) replaced; ``text`` itself
    when there are none. Raises ModelError for an undeclared name or a bad value."""
    if not overrides:
        return text
    for name, value in overrides.items():
        try:
            _check_value(value, f"parameters.{name}")
        except ModelError as e:
            raise e.located(file=file) from None
    try:
        root = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.YAMLError:
        root = None
    params = None
    if isinstance(root, yaml.MappingNode):
        params = next((v for k, v in root.value if k.value == "parameters"), None)
    if not isinstance(params, yaml.MappingNode):
        name = next(iter(overrides))
        raise ModelError(f"cannot set {name!r}: the model file has no parameters mapping to "
                         "override", file=file, field=f"parameters.{name}")
    spans = {}
    for key, node in params.value:
        if key.value in overrides:
            between = text[key.end_mark.index:node.start_mark.index]
            if not _VALUE_START.fullmatch(between):        # an alias: the node is elsewhere
                raise ModelError(f"cannot set {key.value!r}: its value is a YAML alias; write "
                                 "the value itself", file=file, field=f"parameters.{key.value}")
            a, b = node.start_mark.index, node.end_mark.index
            spans[key.value] = (a, a + len(text[a:b].rstrip()))   # a block ends after blanks
    for name in overrides:
        if name not in spans:
            declared = ", ".join(k.value for k, _ in params.value) or "none"
            raise ModelError(f"cannot set {name!r}: it is not a parameter of the model (an "
                             f"override changes a declared parameter; declared: {declared})",
                             file=file, field=f"parameters.{name}")
    for name, (a, b) in sorted(spans.items(), key=lambda kv: -kv[1][0]):
        old = text[a:b]
        text = text[:a] + _flow(overrides[name]) + "\n" * old.count("\n") + text[b:]
    return text

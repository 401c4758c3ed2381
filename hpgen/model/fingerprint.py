"""The normalized model: what of a model file changes the generated code, as plain JSON data.

A cache key must change when, and only when, the emitted code may change. This module
reduces a model file's text to that part, without the compile-time stack (YAML only, no
sympy), so that a cache hit stays cheap:

- the YAML is parsed (hpgen.model.yamldoc), so comments, quoting, key order, indentation and
  flow/block style do not count;
- expressions (the Lagrangian, ``constraints:`` entries, ``record:`` expressions) are reduced to their Python tokens,
  so spaces, line breaks and comments inside them do not count (the tokens, literals
  included, are kept as written: ``1`` and ``1.0`` stay different, as they may change code);
- the scene keeps only what is compiled into kernels: ``record`` (the record kernel's row)
  and ``section`` (the section kernel; its text is also copied into meta.json, so it is
  kept as written). ``h``, ``steps``, ``duration``, ``initial``, ``every`` and ``u`` are run-time
  values and are dropped; any other key is kept (never a false hit);
- ``integrator`` is returned apart (the caller merges it with explicit options);
- every other top-level key (name, group, parameters, schema, and any key a later schema
  adds, such as forces or inputs) is kept as parsed: types included (``1`` is not ``1.0``).

A text that cannot be parsed is returned whole (``{"unparsed": text}``): the derivation
then reports the error with its location. Standard library + PyYAML only.
"""
from __future__ import annotations

import io
import tokenize

from ..errors import ModelError
from .yamldoc import MAX_FILE_BYTES, compose_document

#: scene keys that only the run uses (not compiled into any kernel)
RUN_ONLY_SCENE_KEYS = frozenset(("h", "steps", "duration", "initial", "every", "u"))
#: tokens that never change the parsed expression (a top-level NEWLINE or INDENT may: kept)
_SKIP_TOKENS = frozenset((tokenize.NL, tokenize.DEDENT, tokenize.COMMENT, tokenize.ENDMARKER))


def expression_tokens(text):
    """``text`` as its Python tokens joined by one space (spaces, line breaks inside
    brackets and comments dropped); what does not tokenize (or is no string) is returned
    unchanged."""
    if not isinstance(text, str):
        return text
    try:
        toks = tokenize.generate_tokens(io.StringIO(text.strip()).readline)
        return " ".join(t.string for t in toks if t.type not in _SKIP_TOKENS)
    except (tokenize.TokenError, SyntaxError, ValueError):
        return text


def _record(entries):
    """A ``record:`` list with the expressions of ``{label: expression}`` items tokenized."""
    if not isinstance(entries, list):
        return entries
    return [{k: expression_tokens(v) for k, v in e.items()} if isinstance(e, dict) else e
            for e in entries]


def normalized_model(text: str) -> tuple[dict, object]:
    """(normalized model, the ``integrator:`` section as written or None); see the module
    docstring."""
    try:
        if len(text) > MAX_FILE_BYTES:
            raise ModelError("too large")
        data = compose_document(text, "<model>").data
    except (ModelError, RecursionError, MemoryError, OverflowError, ArithmeticError):
        return {"unparsed": text}, None
    if not isinstance(data, dict):
        return {"unparsed": text}, None
    norm = {k: v for k, v in data.items() if k not in ("integrator", "scene")}
    if "lagrangian" in norm:
        norm["lagrangian"] = expression_tokens(norm["lagrangian"])
    if isinstance(norm.get("constraints"), list):
        norm["constraints"] = [expression_tokens(c) for c in norm["constraints"]]
    scene = data.get("scene")
    if isinstance(scene, dict):
        scene = {k: v for k, v in scene.items() if k not in RUN_ONLY_SCENE_KEYS}
        if "record" in scene:
            scene["record"] = _record(scene["record"])
    norm["scene"] = scene if "scene" in data else "absent"
    return norm, data.get("integrator")

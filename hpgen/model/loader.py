"""The model-file schema (version 1): top-level keys, name, group, parameters, integrator.

Conventions:
- The text is turned into a located document by hpgen.model.yamldoc (lines for every path);
  the Lagrangian is parsed by hpgen.model.expr, the scene by hpgen.model.scene.
- Names (model and parameters) are C identifiers ``[A-Za-z][A-Za-z0-9_]*`` of at most 64
  characters, not C keywords (C99/C11/C23, plus ``main``); parameters may also not be Python
  keywords or names the Lagrangian reserves (xi, g, R, x, functions, pi, xi_k, g_k, R_k, x_k).
- Parameter values: numbers, non-empty lists of numbers, rectangular lists of lists; finite.
  ``Model.parameters`` stores them as floats / tuples; the Lagrangian gets ints as exact Integers.
- Every problem raises hpgen.errors.ModelError naming file, line, field and what was expected.
"""
from __future__ import annotations

import functools
import keyword
import os
import re
import stat

from ..errors import ModelError
from ..schemes import RKMK, TAU
from .names import check_identifier
from .open_keys import (_forces, _inputs, _refuse_runtime_in_scene, _refuse_unforced_work,
                        _runtime_parameters)
from .types import RESERVED_NAMES, IntegratorChoice, Model
from .yamldoc import MAX_FILE_BYTES, Doc, compose_document, describe, is_number

MAX_MATRIX_SIZE = 64                # n and d of the group (g has n*n symbols)
#: n and d of a family G^N (hpgen.model.families): derived body by body, not as one matrix
MAX_FAMILY_MATRIX_SIZE = 1024

TOP_KEYS = ("schema", "name", "group", "parameters", "lagrangian", "integrator", "scene",
            "runtime_parameters", "inputs", "forces", "constraints")
INTEGRATOR_KEYS = ("tableau", "tau", "rkmk", "compose")

_FACTOR_NAME = re.compile(r"(xi|g|R|x)_[0-9]+")


# ---- the schema --------------------------------------------------------------------------------
def _check_parameter_name(doc: Doc, path, name) -> None:
    check_identifier(doc, path, name, "parameter name")
    if name in RESERVED_NAMES or name == "pi" or _FACTOR_NAME.fullmatch(name):
        raise doc.error(path, f"parameter name {name!r} is reserved for the Lagrangian "
                              f"(reserved: {', '.join(RESERVED_NAMES)}, pi, xi_k, g_k, R_k, x_k)")
    if keyword.iskeyword(name):
        raise doc.error(path, f"parameter name {name!r} is a Python keyword and could not be "
                              "used in the Lagrangian; choose another name")


def _parameter_value(doc: Doc, path, v):
    if isinstance(v, list) and v and all(isinstance(r, list) for r in v):
        return doc.matrix(path, v)
    if isinstance(v, list):
        if any(isinstance(r, (list, dict)) for r in v):
            raise doc.error(path, "expected a number, a list of numbers or a list of lists "
                                  "of numbers (a matrix)")
        return doc.vector(path, v)
    if is_number(v):
        return doc.number(path, v)
    raise doc.error(path, "expected a number, a non-empty list of numbers or a rectangular list "
                          f"of lists of numbers, got {describe(v)}"
                    + (" (quoted strings are not numbers)" if isinstance(v, str) else ""))


def _parameters(doc: Doc, raw) -> tuple[tuple, dict]:
    """((name, stored value), ...) with floats, and {name: exact value} for the expression."""
    if raw is None:
        return (), {}
    if not isinstance(raw, dict):
        raise doc.error(("parameters",), f"expected a mapping name: value, got {describe(raw)}")
    stored, exact = [], {}
    for name, v in raw.items():
        path = ("parameters", name)
        _check_parameter_name(doc, path, name)
        stored.append((name, _parameter_value(doc, path, v)))
        exact[name] = v                       # ints stay ints (exact sympy Integers)
    return tuple(stored), exact


def _group(doc: Doc, spec, params: dict):
    from .families import family_of, group_of_spec
    try:
        group = group_of_spec(spec, params)
    except ModelError as e:
        path = tuple(e.field.split(".")) if e.field and e.field != "group" else ("group",)
        raise e.located(doc.file, "group", doc.line(path)) from None
    limit = MAX_MATRIX_SIZE if family_of(group) is None else MAX_FAMILY_MATRIX_SIZE
    if group.n > limit or group.d > limit:
        raise doc.error(("group",), f"group too large: matrix size {group.n}, dimension "
                                    f"{group.d} (limit {limit} each)")
    return group


def _tableau(doc: Doc, raw):
    from ..tableaus import ButcherTableau, get_tableau
    path = ("integrator", "tableau")
    if isinstance(raw, str):
        try:
            get_tableau(raw)
        except ModelError as e:
            raise ModelError(e.message, file=doc.file, field="integrator.tableau",
                             line=doc.line(path)) from None
        return raw
    if not isinstance(raw, dict):
        raise doc.error(path, f"expected a tableau name or a mapping {{A: [[...]], b: [...]}} "
                              f"(c optional), got {describe(raw)}")
    doc.mapping(path, raw, ("A", "b", "c"))
    for k in ("A", "b"):
        if k not in raw:
            raise doc.error(path, f"a user tableau needs {k}: expected {{A: [[...]], b: [...]}}")
    A = doc.matrix(path + ("A",), raw["A"])
    b = doc.vector(path + ("b",), raw["b"])
    c = doc.vector(path + ("c",), raw["c"]) if raw.get("c") is not None else None
    try:
        return ButcherTableau.from_user([list(r) for r in A], list(b),
                                        None if c is None else list(c))
    except ModelError as e:
        raise ModelError(e.message, file=doc.file, field="integrator.tableau",
                         line=doc.line(path)) from None
    except (ValueError, TypeError, ArithmeticError) as e:
        raise doc.error(path, f"invalid tableau: {e}") from None


def _integrator(doc: Doc, raw) -> IntegratorChoice:
    raw = doc.mapping(("integrator",), raw, INTEGRATOR_KEYS)
    kw = {}
    for option in (TAU, RKMK):
        key = option.name
        if raw.get(key) is not None:
            try:
                kw[key] = option.check(raw[key], field=f"integrator.{key}", show=describe)
            except ModelError as e:
                raise doc.error(("integrator", key), e.message) from None
    if raw.get("tableau") is not None:
        kw["tableau"] = _tableau(doc, raw["tableau"])
    if raw.get("compose") is not None:
        from ..tableaus.composition import get_composition
        try:
            kw["compose"] = get_composition(raw["compose"]).name
        except ModelError as e:
            raise doc.error(("integrator", "compose"), e.message) from None
    return IntegratorChoice(**kw)


def _lagrangian(doc: Doc, text, group, exact_params, refused=None):
    from .expr import parse_lagrangian
    from .symbols import TIME_SYMBOL
    if is_number(text):
        raise doc.error(("lagrangian",), f"the Lagrangian does not depend on xi (it is the "
                                         f"constant {text!r}); it must contain the velocity xi")
    if not isinstance(text, str) or not text.strip():
        raise doc.error(("lagrangian",), "expected an expression in xi (and g, parameters), "
                                         f"e.g. 0.5*(xi[0]**2 + xi[1]**2), got {describe(text)}")
    try:
        return parse_lagrangian(text, group, exact_params, extra={"t": TIME_SYMBOL},
                                refused=refused)
    except ModelError as e:
        line = doc.line(("lagrangian",))
        if line and doc.lagrangian_style == "|" and getattr(e, "expr_line", None):
            line += e.expr_line
        raise e.located(doc.file, "lagrangian", line) from None


def _family(group, text: str, exact):
    """The BodyFamily of a model on G^N with its Lagrangian's sums (None otherwise)."""
    from .families import family_of, with_sums
    from .syntax import parse_checked
    family = family_of(group)
    return None if family is None else with_sums(family, text, parse_checked(text), exact)



def _expanded(doc: Doc, text, group, lag_params: dict, refused: dict):
    """The expanded Lagrangian (sympy) of a model loaded without it (Model.lagrangian)."""
    return _lagrangian(doc, text, group, lag_params, refused)[0]


def build_model(doc: Doc, text: str) -> Model:
    from .symbols import input_symbol
    data = doc.mapping((), doc.data, TOP_KEYS)
    if "schema" in data and (type(data["schema"]) is not int or data["schema"] != 1):
        raise doc.error(("schema",), f"unsupported schema {data['schema']!r}: expected 1")
    for key in ("name", "group", "lagrangian"):
        if data.get(key) is None:
            what = "missing required key" if key not in data else "empty value for required key"
            raise doc.error((key,), f"{what} {key!r} (a model needs name, group and lagrangian)")
    name = check_identifier(doc, ("name",), data["name"], "model name")
    stored, exact = _parameters(doc, data.get("parameters"))
    group = _group(doc, data["group"], exact)
    runtime, rsyms, rdefaults, lag_params = _runtime_parameters(
        doc, data.get("runtime_parameters"), stored, exact)
    inputs = _inputs(doc, data.get("inputs"), stored)
    integrator = _integrator(doc, data.get("integrator"))
    refused = {u: f"the input {u!r} may not appear in the Lagrangian (control inputs enter "
                  "through forces only)" for u in inputs}
    from .family_load import local_lagrangian
    fast = local_lagrangian(group, data["lagrangian"], exact, lag_params, refused)
    build = functools.partial(_expanded, doc, data["lagrangian"], group, lag_params, refused)
    if fast is not None:             # a family whose sums are local: not expanded here
        family, body_lag, xi_syms, g_syms = fast
        lag = None
    else:
        lag, xi_syms, g_syms = _lagrangian(doc, data["lagrangian"], group, lag_params, refused)
        family, body_lag = _family(group, data["lagrangian"], exact), None
    checked = lag if lag is not None else body_lag     # what the constraint checks read
    forces, forces_text, body_force = (), (), None
    if isinstance(data.get("forces"), dict):      # per body: {for: i, body: [...]}
        from .family_forces import parse_family_forces
        forces, forces_text, body_force = parse_family_forces(
            doc, data["forces"], group, lag_params, inputs, xi_syms, g_syms)
    elif data.get("forces") is not None:
        forces, forces_text = _forces(doc, data["forces"], group, lag_params, inputs)
    scene = None
    if data.get("scene") is not None:
        from .scene import parse_scene
        scene = parse_scene(doc, data["scene"], group, lag_params, inputs)
        _refuse_runtime_in_scene(doc, scene, rsyms)
        _refuse_unforced_work(doc, scene, forces)
    constraints = ()
    if data.get("constraints") is not None:
        from .constraints import parse_constraints
        constraints = parse_constraints(doc, data["constraints"], group, exact,
                                        [nm for nm, _ in runtime], g_syms,
                                        (checked, xi_syms, dict(zip(rsyms, rdefaults))))
    if scene is not None and (constraints or scene.project):
        from .constraints import check_initial
        scene = check_initial(doc, constraints, g_syms, group, scene,      # its metric: l's
                              (checked, xi_syms, dict(zip(rsyms, rdefaults))))
    if family is not None:
        from dataclasses import replace
        from .bodyterms import local_terms
        local = local_terms(family, constraints, lag_params)
        if local is not None and body_force is not None:
            from .bodyterms import sorted_data
            local = replace(local, force=body_force,
                            data=sorted_data({**dict(local.data), **dict(body_force.data)}))
        family = replace(family, local=local)
    return Model(name=name, path=doc.file, source=text, group_spec=data["group"], group=group,
                 parameters=stored, lagrangian_text=data["lagrangian"], lagrangian_expr=lag,
                 xi_symbols=xi_syms, g_symbols=g_syms, integrator=integrator, scene=scene,
                 runtime_parameters=runtime, runtime_symbols=rsyms, runtime_defaults=rdefaults,
                 inputs=inputs, input_symbols=tuple(input_symbol(u) for u in inputs),
                 forces=forces, forces_text=forces_text, constraints=constraints,
                 family=family, lagrangian_builder=build)


def load_model_text(text, filename: str = "<string>") -> Model:
    """Validate model-file text; every problem is a one-line hpgen.errors.ModelError."""
    file = str(filename)
    if isinstance(text, (bytes, bytearray)):
        try:
            text = bytes(text).decode("utf-8")
        except UnicodeDecodeError as e:
            raise ModelError(f"the model file is not UTF-8 text ({e.reason} at byte {e.start})",
                             file=file) from None
    if not isinstance(text, str):
        raise ModelError(f"expected the model file's text, got {type(text).__name__}", file=file)
    if len(text) > MAX_FILE_BYTES or len(text.encode("utf-8", "surrogatepass")) > MAX_FILE_BYTES:
        raise ModelError(f"the model file is too large (limit {MAX_FILE_BYTES // 1024 // 1024} MB)",
                         file=file)
    try:
        return build_model(compose_document(text, file), text)
    except RecursionError:
        raise ModelError("the model is too deeply nested", file=file) from None
    except MemoryError:
        raise ModelError("out of memory while reading the model (is it too large?)",
                         file=file) from None
    except (OverflowError, ArithmeticError) as e:
        raise ModelError(f"numeric overflow while reading the model: {e}", file=file) from None


def read_model_bytes(path) -> bytes:
    """The bytes of a model file: a regular file (after symlinks) of at most MAX_FILE_BYTES.
    A device (/dev/zero), FIFO, socket or directory is refused before anything is read (a
    FIFO is opened non-blocking, so it never hangs); at most MAX_FILE_BYTES + 1 bytes are
    read, so a file that grows while it is read cannot exhaust memory."""
    file = os.fspath(path)
    limit = f"limit {MAX_FILE_BYTES // 1024 // 1024} MB"
    try:
        fd = os.open(file, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as e:
        raise ModelError(f"cannot read the model file ({e.strerror or e})", file=file) from None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise ModelError(f"expected a regular file, got {_file_kind(st.st_mode)}", file=file)
        if st.st_size > MAX_FILE_BYTES:
            raise ModelError(f"the model file is too large ({st.st_size} bytes; {limit})",
                             file=file)
        chunks, size = [], 0
        while size <= MAX_FILE_BYTES:
            block = os.read(fd, MAX_FILE_BYTES + 1 - size)
            if not block:
                break
            chunks.append(block)
            size += len(block)
    except OSError as e:
        raise ModelError(f"cannot read the model file ({e.strerror or e})", file=file) from None
    finally:
        os.close(fd)
    if size > MAX_FILE_BYTES:
        raise ModelError(f"the model file is too large ({limit})", file=file)
    return b"".join(chunks)


def _file_kind(mode) -> str:
    for test, name in ((stat.S_ISDIR, "a directory"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return name
    return "a special file"


def load_model(path) -> Model:
    """Read and validate a model file (at most 2 MB of UTF-8 YAML; read_model_bytes)."""
    return load_model_text(read_model_bytes(path), filename=os.fspath(path))

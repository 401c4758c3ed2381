"""Models declared in Python: a mapping with the model file's keys, or a ModelBuilder whose
Lagrangian and forces are SymPy expressions in symbols it hands out.

Both become model-file text (``model_text``) that the loader checks like any file, so a
model from Python obeys the same rules, fails with the same one-line errors (file
``<mapping>``, the field, no line) and gives the module of the equivalent YAML file (the same
content hash: the hash is taken of the parsed document, hpgen.model.fingerprint).

- A mapping: the keys of docs/model-file.md; values are str, int, float, bool, None, lists or
  tuples, mappings with string keys, and numpy arrays or scalars (as lists and numbers).
  Expressions are strings in the model language, as in a file.
- A ModelBuilder: SymPy expressions are printed into the model language by
  ``ModelPrinter`` (symbols by their model-language name, floats as their shortest round-trip
  decimal, rationals as ``p/q``) and the text is parsed by the same whitelist parser as a
  file's; a symbol the builder did not hand out, or a function or constant outside the
  language, is a ModelError naming the field. Nothing is evaluated: SymPy is only printed.

Symbols a builder hands out (SymPy Symbols named as in the model language): ``xi`` (d), ``g``
(n x n), ``R`` and ``x`` (groups with a rotation / translation block), ``t``, each parameter
(a Symbol, or a Matrix of Symbols for a vector or matrix value) and each input.
"""
from __future__ import annotations

import functools
import math
from collections.abc import Mapping

from ..errors import ModelError

#: the file name of a model given as a mapping or a builder, in errors and CompiledModule.source
MAPPING_SOURCE = "<mapping>"


def without_line(err: ModelError, path: str) -> ModelError:
    """``err`` of the model named ``path``; a model from Python has no lines to point at, so
    its errors name the field only."""
    if path != MAPPING_SOURCE:
        return err
    return ModelError(err.message, file=path, field=err.field)


# ---- a mapping -> model-file text ----------------------------------------------------------
def _plain(value, path: str):
    """value as plain YAML-able data (dict, list, str, int, float, bool, None)."""
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, float):
        return float(value)             # numpy.float64 is a float subclass
    if isinstance(value, int):
        return int(value)
    if isinstance(value, Mapping):
        out = {}
        for k, v in value.items():
            if not isinstance(k, str):
                raise ModelError(f"mapping keys must be strings, got {type(k).__name__} {k!r}",
                                 file=MAPPING_SOURCE, field=path or None)
            out[k] = _plain(v, f"{path}.{k}" if path else k)
        return out
    if isinstance(value, (list, tuple)):
        return [_plain(v, f"{path}[{i}]") for i, v in enumerate(value)]
    kind = type(value).__module__.split(".")[0]
    if kind == "numpy":
        import numpy as np
        if isinstance(value, np.ndarray):
            return _plain(value.tolist(), path)
        if isinstance(value, np.generic):
            return _plain(value.item(), path)
    if kind == "sympy":
        raise ModelError("a SymPy expression in a mapping: give the model-language text, or "
                         "declare the model with hpgen.model.builder.ModelBuilder",
                         file=MAPPING_SOURCE, field=path or None)
    raise ModelError(f"expected a number, string, list or mapping, got {type(value).__name__}",
                     file=MAPPING_SOURCE, field=path or None)


def model_text(model) -> str:
    """The model-file text of a mapping with the model file's keys, or of a ModelBuilder."""
    if isinstance(model, ModelBuilder):
        model = model.to_mapping()
    if not isinstance(model, Mapping):
        raise ModelError(f"expected a mapping with the model file's keys, got "
                         f"{type(model).__name__}", file=MAPPING_SOURCE)
    import yaml
    data = _plain(model, "")
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True, width=10**6,
                          default_flow_style=None)


# ---- SymPy -> the model language -----------------------------------------------------------
@functools.lru_cache(maxsize=1)
def _printer_class():
    from sympy.printing.str import StrPrinter

    class ModelPrinter(StrPrinter):
        """SymPy -> model-language text; only the builder's symbols and the language's
        functions (sin cos tan exp log sqrt), pi and numbers are printed, anything else is
        a ModelError naming ``field``."""

        def __init__(self, symbols, field):
            super().__init__({"full_prec": True})
            self.symbols, self.field = symbols, field

        def _refuse(self, what):
            raise ModelError(f"{what} is not in the model language (allowed: the builder's "
                             "symbols, numbers, pi, + - * / **, sin cos tan exp log sqrt)",
                             file=MAPPING_SOURCE, field=self.field)

        def _print_Symbol(self, expr):
            if self.symbols.get(expr.name) != expr:
                self._refuse(f"the symbol {expr.name!r} (not handed out by this builder)")
            return expr.name

        def _print_Float(self, expr):
            value = float(expr)
            if not math.isfinite(value):
                self._refuse(f"the number {value!r}")
            return repr(value)

        def _print_Function(self, expr):
            name = type(expr).__name__
            if name not in ("sin", "cos", "tan", "exp", "log") or len(expr.args) != 1:
                self._refuse(f"the function {name}")
            return f"{name}({self._print(expr.args[0])})"

        def _print_Exp1(self, expr):
            return "exp(1)"

        def _print_Pi(self, expr):
            return "pi"

        def emptyPrinter(self, expr):
            self._refuse(f"{type(expr).__name__} {str(expr)[:40]!r}")

    for name in ("ImaginaryUnit", "Infinity", "NegativeInfinity", "ComplexInfinity", "NaN",
                 "Derivative", "Integral", "Piecewise", "Abs", "Min", "Max", "Order",
                 "MatrixBase", "Relational", "BooleanTrue", "BooleanFalse", "Lambda",
                 "Subs", "Sum", "Product", "ExprCondPair", "Mod", "floor", "ceiling"):
        setattr(ModelPrinter, f"_print_{name}", ModelPrinter.emptyPrinter)
    return ModelPrinter


def to_model_text(expr, symbols: dict, field: str):
    """The model-language text of the SymPy scalar ``expr`` in ``symbols`` ({name: Symbol});
    text and Python numbers are returned as they are (the loader checks them, as in a file).
    ModelError naming ``field`` for anything outside the language."""
    import sympy as sp
    if isinstance(expr, str) or isinstance(expr, (int, float)) and not isinstance(expr, bool):
        return expr                     # text or a number, as in a file: checked by the loader
    if not isinstance(expr, sp.Expr) or isinstance(expr, sp.MatrixBase):
        raise ModelError(f"expected a SymPy scalar expression or a number, got "
                         f"{type(expr).__name__}", file=MAPPING_SOURCE, field=field)
    return _printer_class()(symbols, field).doprint(expr)


# ---- the builder ---------------------------------------------------------------------------
class ModelBuilder:
    """A model declared in Python: ``ModelBuilder(name, group)``, then ``parameter``,
    ``input``, and the attributes ``lagrangian`` (a SymPy expression or model-language text),
    ``forces`` (d of them, or None), ``integrator`` and ``scene`` (mappings as in a model file).
    ``hpgen.compile(builder)`` compiles it; ``to_mapping()`` / ``to_yaml()`` give the
    equivalent model file. Symbols: ``xi``, ``g``, ``R``, ``x``, ``t`` (module docstring)."""

    def __init__(self, name: str, group):
        from ..errors import ArgumentError
        from ..groups.elements import factor_layout, factor_names
        self.name, self.group = name, group
        spec = group if isinstance(group, str) else "[" + ", ".join(map(str, group)) + "]"
        try:
            layouts = [factor_layout(f) for f in factor_names(spec)]
        except ArgumentError as e:
            raise ModelError(e.message + " (expected R<n>, SO2, SO3, SE2, SE3 or a list of "
                             "them)", file=MAPPING_SOURCE, field="group") from None
        n = sum(lay[0] for lay in layouts)
        d = sum(lay[0] - 1 if lay[1] is None else
                (lay[1][1] - lay[1][0]) * (lay[1][1] - lay[1][0] - 1) // 2 +
                (0 if lay[2] is None else lay[2][1] - lay[2][0]) for lay in layouts)
        self._symbols: dict = {}
        self.parameters: dict = {}
        self.runtime_parameters: list = []
        self.inputs: list = []
        self.lagrangian = None
        self.forces = None
        self.integrator: dict | None = None
        self.scene: dict | None = None
        self.xi = self._vector("xi", d)
        self.g = self._matrix("g", n, n)
        self.t = self._symbol("t")
        self.R = self.x = None
        if len(layouts) == 1 and layouts[0][1] is not None:
            a, b = layouts[0][1]
            self.R = self._matrix("R", b - a, b - a)
        if len(layouts) == 1 and layouts[0][2] is not None:
            a, b = layouts[0][2]
            self.x = self._vector("x", b - a)

    def _symbol(self, name):
        import sympy as sp
        s = sp.Symbol(name, real=True)
        self._symbols[name] = s
        return s

    def _vector(self, name, k):
        import sympy as sp
        return sp.Matrix([self._symbol(f"{name}[{i}]") for i in range(k)])

    def _matrix(self, name, r, c):
        import sympy as sp
        return sp.Matrix(r, c, lambda i, j: self._symbol(f"{name}[{i}, {j}]"))

    def parameter(self, name: str, value, runtime: bool = False):
        """Declare a parameter (a number, a list of numbers or a list of lists, as in a model
        file; ``runtime=True`` lists it in ``runtime_parameters``) and return its symbol: a
        Symbol, or a Matrix of Symbols ``name[i]`` / ``name[i, j]``."""
        import numpy as np
        if name in self.parameters:
            raise ModelError(f"{name!r} is declared twice", file=MAPPING_SOURCE,
                             field=f"parameters.{name}")
        value = _plain(value, f"parameters.{name}")
        self.parameters[name] = value
        if runtime:
            self.runtime_parameters.append(name)
        shape = np.shape(value) if isinstance(value, list) else ()
        if len(shape) == 1:
            return self._vector(name, shape[0])
        if len(shape) == 2:
            return self._matrix(name, *shape)
        return self._symbol(name)

    def input(self, name: str):
        """Declare a control input (``inputs:``) and return its Symbol."""
        self.inputs.append(name)
        return self._symbol(name)

    def to_mapping(self) -> dict:
        """The model as a mapping with the model file's keys (expressions as text)."""
        if self.lagrangian is None:
            raise ModelError("missing required key 'lagrangian' (set builder.lagrangian)",
                             file=MAPPING_SOURCE, field="lagrangian")
        out: dict = {"name": self.name, "group": self.group}
        if self.parameters:
            out["parameters"] = dict(self.parameters)
        if self.runtime_parameters:
            out["runtime_parameters"] = list(self.runtime_parameters)
        if self.inputs:
            out["inputs"] = list(self.inputs)
        out["lagrangian"] = to_model_text(self.lagrangian, self._symbols, "lagrangian")
        if self.forces is not None:
            forces = list(self.forces)
            out["forces"] = [to_model_text(f, self._symbols, f"forces[{i}]")
                             for i, f in enumerate(forces)]
        if self.integrator is not None:
            out["integrator"] = self.integrator
        if self.scene is not None:
            out["scene"] = self.scene
        return out

    def to_yaml(self) -> str:
        """The equivalent model file's text."""
        return model_text(self.to_mapping())

"""The options of one compile (CompileOptions: checked, keyed) and the model's source: a
model file's text, or the text of a model declared in Python (hpgen.model.builder); the
scheme a compile uses (``resolve``: explicit options over the model's ``integrator:``)."""
from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .errors import ModelError
from .schemes import BACKEND, RKMK, TAU


@dataclass(frozen=True)
class CompileOptions:
    """Explicit options of one compile (no global configuration)."""
    tableau: object = None        # catalog name, {"A": ..., "b": ...}, ButcherTableau or None
    tau: str | None = None
    rkmk: str | None = None
    backend: str = "c"
    out: str | Path | None = None  # directory receiving <module>/; None: use the cache entry
    cache_dir: str | Path | None = None
    cc: str | None = None
    cflags: tuple[str, ...] | None = None
    #: parameter overrides ((name, value), ...) applied to the model text (model.overrides)
    parameters: tuple | None = None
    #: the Newton matrix's storage: None (hpgen.derive.sparse_jacobian's rule), "sparse", "dense"
    jacobian: str | None = None
    #: a composition of the step (hpgen.tableaus.composition; None: the model's
    #: integrator.compose, else the plain step). Not in the cache key: the kernels are the
    #: plain step's; the loaded runtime composes them.
    compose: str | None = None

    def validate(self):
        for option, value in ((TAU, self.tau), (RKMK, self.rkmk), (BACKEND, self.backend)):
            if value is not None:
                option.check(value, field=f"option {option.name}")
        if self.compose is not None:
            from .tableaus.composition import get_composition
            try:
                get_composition(self.compose)
            except ModelError as e:
                raise ModelError(e.message, field="option compose") from None
        if self.jacobian not in (None, "sparse", "dense"):
            raise ModelError(f"expected sparse or dense, got {self.jacobian!r}",
                             field="option jacobian")
        if self.tableau is not None and not isinstance(self.tableau, (str, dict)) \
                and not hasattr(self.tableau, "A"):
            raise ModelError("expected a catalog name or {A: [[...]], b: [...]}",
                             field="option tableau")

    def key(self) -> str:
        """The part of the cache key that the options contribute (code-changing only)."""
        tab: Any = self.tableau
        if tab is not None and not isinstance(tab, (str, dict)):
            tab = {"A": [list(r) for r in tab.A], "b": list(tab.b), "name": tab.name}
        key = {"tableau": tab, "tau": self.tau, "rkmk": self.rkmk}
        if self.jacobian is not None:
            key["jacobian"] = self.jacobian
        return json.dumps(key, sort_keys=True, default=repr)


def read_model_text(path) -> str:
    """The text of a model file (hpgen.model.loader.read_model_bytes: a regular file of at
    most 2 MB, never read past that), decoded as UTF-8."""
    from .model.loader import read_model_bytes
    data = read_model_bytes(path)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise ModelError("expected a UTF-8 text file", file=str(path)) from None


def model_source(model) -> tuple[str, str]:
    """(name, text) of a model given as a model file's path, a mapping with the model file's
    keys or a hpgen.model.builder.ModelBuilder (name ``<mapping>``; hpgen.model.builder)."""
    if isinstance(model, (str, os.PathLike)):
        return os.fspath(model), read_model_text(model)
    if isinstance(model, Mapping) or hasattr(model, "to_mapping"):
        from .model.builder import MAPPING_SOURCE, model_text
        return MAPPING_SOURCE, model_text(model)
    raise ModelError("expected the path of a model file, a mapping with the model file's keys "
                     f"or a hpgen.model.builder.ModelBuilder, got {type(model).__name__}",
                     field="model")


def resolve(model_obj, opts: CompileOptions):
    """The (ButcherTableau, tau, rkmk) a compile uses: explicit options over model defaults."""
    from .tableaus import ButcherTableau, resolve_tableau
    spec = opts.tableau if opts.tableau is not None else model_obj.integrator.tableau
    if isinstance(spec, dict):
        if set(spec) - {"A", "b", "c"} or not {"A", "b"} <= set(spec):
            raise ModelError("expected {A: [[...]], b: [...]} with an optional c",
                             field="option tableau")
        tag = hashlib.sha256(json.dumps(spec, sort_keys=True, default=repr).encode()).hexdigest()
        tab = ButcherTableau.from_user(spec["A"], spec["b"], spec.get("c"), name=f"user{tag[:8]}")
    else:
        tab = resolve_tableau(spec)
    return tab, opts.tau or model_obj.integrator.tau, opts.rkmk or model_obj.integrator.rkmk

"""The compile-time stages of one compile: model text -> parsed model and resolved scheme
-> derived step (Derivation) -> the generated module's files. Imports sympy and casadi
(hpgen.api calls these only when the build cache misses)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .compile_options import CompileOptions, resolve
from .errors import ModelError


#: the source each backend builds from: a cache entry holds those of the backends asked for
#: so far (the other is generated on first use: a C compile writes no kernels.py)
BACKEND_SOURCES = {"c": "kernels.c", "python": "kernels.py"}


@dataclass(frozen=True)
class Derivation:
    """The derive stage's result for one compile: the parsed model, the resolved tableau
    (a ButcherTableau), tau and rkmk, and the DiscreteStep."""
    model: Any
    tableau: Any
    tau: str
    rkmk: str
    step: Any


def generate_files(path: str, text: str, opts: CompileOptions, key: str) -> dict[str, str]:
    """Run the pipeline model -> derive -> codegen; the files of the generated module (both
    backends' sources)."""
    return emit_files(derive_module(path, text, opts), text, opts, key)


def derive_module(path: str, text: str, opts: CompileOptions) -> Derivation:
    """The model (text of the file ``path``) parsed, its options resolved and its step
    derived and checked. Raises ModelError naming the file."""
    from .model import load_model_text
    from .model.builder import without_line
    try:
        model_obj = load_model_text(text, filename=path)   # bad input fails before casadi
    except ModelError as e:
        raise without_line(e, path) from None
    from .derive import derive
    from .derive.checks import check_legendre
    try:
        tab, tau, rkmk = resolve(model_obj, opts)
        step = derive(model_obj, tab, tau, rkmk, opts.jacobian)
        check_legendre(step, model_obj)
    except ModelError as e:          # errors of the options and the derivation name the file too
        raise without_line(e.located(file=path), path) from None
    return Derivation(model_obj, tab, tau, rkmk, step)


def emit_files(d: Derivation, text: str, opts: CompileOptions, key: str,
               sources=tuple(BACKEND_SOURCES.values())) -> dict[str, str]:
    """The files of the generated module of a derivation (codegen): meta.json, __init__.py,
    model.yaml and the backend sources named in ``sources`` (kernels.c, kernels.py)."""
    from .codegen import emit, module_name
    name = module_name(d.model.name, d.tableau.name, d.tau, d.rkmk)
    gm = emit(d.step, {"module": name, "model_name": d.model.name, "model_source": text,
                       "options": {"tableau": d.tableau.name, "tau": d.tau, "rkmk": d.rkmk},
                       "hash": key, "backend": opts.backend}, sources=sources)
    return dict(gm.files)

"""emit(): DiscreteStep + caller info -> the files of one generated module (pure, no file I/O).

Generated files (relative paths):
  kernels.c    CasADi's C for all kernels + templates/kernels.c.j2 (LU, Newton, step, runs);
               status codes and Newton constants from hpgen.abi
  kernels.py   the Python backend printed from the same SX algorithms (templates/kernels.py.j2)
  __init__.py  lazy wrapper: integrator(backend=None), step(g, p, h), simulate(**kw),
               record(**kw)
  meta.json    dimensions, options, kernel signatures, CasADi work sizes (sorted keys)
  model.yaml   the model source, as is
Output is deterministic: the same step and info give the same bytes. Every code file starts
with a header comment naming model, options, hpgen version and the caller's content hash.
"""
from __future__ import annotations

import json
import keyword
import re
from dataclasses import dataclass
from pathlib import Path

import jinja2

from .. import __version__, abi
from ..schemes import BACKENDS, OPTION_KEYS
from .contract import HASH_RE, MODULE_RE, CodegenError, check_step
from .csource import c_kernel_context, casadi_c_code, work_sizes
from . import pylinear
from .pysource import py_kernel_context

META_FORMAT = abi.META_FORMAT
TEMPLATES = {"kernels.c": "kernels.c.j2", "kernels.py": "kernels.py.j2",
             "__init__.py": "__init__.py.j2"}
#: math functions the Python backend wraps: (math name, numpy name of the IEEE fallback)
SAFE_UNARY = (("exp", "exp"), ("log", "log"), ("sqrt", "sqrt"), ("sin", "sin"),
              ("cos", "cos"), ("tan", "tan"), ("asin", "arcsin"), ("acos", "arccos"),
              ("sinh", "sinh"), ("cosh", "cosh"), ("acosh", "arccosh"),
              ("atanh", "arctanh"), ("log1p", "log1p"), ("expm1", "expm1"))
#: kernels the C step calls; when their CasADi instructions total at most
#: FLATTEN_MAX_INSTRUCTIONS they are inlined into the step (faster, compile time stays small)
STEP_KERNELS = ("residual", "residual_jacobian", "update", "margin")
FLATTEN_MAX_INSTRUCTIONS = 2000
_SAFE_CHARS = re.compile(r"[^A-Za-z0-9 _.,:;=+\-()\[\]{}<>#@%&!?'|^~$]")


@dataclass(frozen=True)
class GeneratedModule:
    """name: the module (package) name; files: ((relative_path, text), ...) in write order."""
    name: str
    files: tuple

    def file(self, path: str) -> str:
        for p, text in self.files:
            if p == path:
                return text
        raise KeyError(path)


def template_dir() -> Path:
    import hpgen
    return Path(hpgen.__file__).resolve().parents[1] / "templates"


def environment() -> jinja2.Environment:
    return jinja2.Environment(loader=jinja2.FileSystemLoader(str(template_dir())),
                              undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
                              trim_blocks=True, lstrip_blocks=True, autoescape=False)


def module_name(model_name: str, tableau: str, tau: str, rkmk: str) -> str:
    """``heavy_top_gauss2_exp_exact``: parts joined by ``_``, other characters -> ``_``."""
    name = re.sub(r"[^A-Za-z0-9_]", "_", "_".join(str(s) for s in
                                                  (model_name, tableau, tau, rkmk)))
    return _check_module(name)


def _check_module(name) -> str:
    if not isinstance(name, str) or not MODULE_RE.match(name) or keyword.iskeyword(name):
        raise CodegenError(f"module name {name!r} is not valid: it must match "
                           "[A-Za-z][A-Za-z0-9_]{0,127} (start with a letter, at most 128 "
                           "characters); rename the model")
    return name


def _safe(text) -> str:
    """Text safe inside a C comment, a Python comment and a docstring (one line, no '*/',
    no quotes or backslashes)."""
    return _SAFE_CHARS.sub("?", str(text)).replace("*", "?")


def _check_info(info: dict) -> dict:
    if not isinstance(info, dict):
        raise CodegenError("info must be a dict")
    missing = [k for k in ("module", "model_name", "model_source", "options", "hash")
               if k not in info]
    if missing:
        raise CodegenError(f"info is missing {missing}")
    module = _check_module(info["module"])
    opts = info["options"]
    if (not isinstance(opts, dict) or not all(isinstance(opts.get(k), str) for k in OPTION_KEYS)
            or not all(isinstance(k, str) and isinstance(v, (str, int, float, bool))
                       for k, v in opts.items())):
        raise CodegenError(f"info['options'] must map {OPTION_KEYS} to strings (extra keys: "
                           "JSON scalars)")
    if not isinstance(info["hash"], str) or not HASH_RE.match(info["hash"]):
        raise CodegenError("info['hash'] must be 16 to 128 lowercase hex digits")
    backend = info.get("backend", "c")
    if backend not in BACKENDS:
        raise CodegenError(f"info['backend'] must be one of {BACKENDS}, got {backend!r}")
    if not isinstance(info["model_source"], str) or not isinstance(info["model_name"], str):
        raise CodegenError("info['model_name'] and info['model_source'] must be strings")
    return {"module": module, "model_name": info["model_name"],
            "model_source": info["model_source"], "options": dict(opts),
            "hash": info["hash"], "backend": backend}


def header_lines(info: dict) -> list[str]:
    o = info["options"]
    return [f"hpgen generated module {info['module']} -- do not edit, regenerate with hpgen",
            f"model: {_safe(info['model_name'])}",
            "options: " + ", ".join(f"{k}={_safe(o[k])}" for k in OPTION_KEYS),
            f"hpgen version: {__version__}",
            f"content hash: {info['hash']}"]


def _step_instructions(step) -> int:
    """CasADi instructions of the kernels one C step calls."""
    return sum(step.kernel(k).function.n_instructions() for k in STEP_KERNELS)


def _python_linear(nz: int) -> dict:
    """kernels.py's Newton linear algebra: printed for nz <= pylinear.UNROLL_MAX."""
    if nz > pylinear.UNROLL_MAX:
        return {"linear_source": "", "unit_rows": "", "linear_functions": [],
                "unroll_max": pylinear.UNROLL_MAX}
    return {"linear_source": pylinear.linear_solver_source(nz).rstrip("\n"),
            "unit_rows": repr(pylinear.unit_rows(nz)),
            "linear_functions": list(pylinear.FUNCTIONS), "unroll_max": pylinear.UNROLL_MAX}


def c_abi_context() -> dict:
    """kernels.c.j2's share of hpgen.abi: the ABI version, the status codes (code, name,
    message) and the Newton constants, printed as C literals that read back bitwise."""
    return dict({k: abi.c_literal(v) for k, v in abi.TEMPLATE_CONSTANTS.items()},
                status=[list(s) for s in abi.STATUS], status_invalid=abi.INVALID)


def template_contexts(step, info: dict) -> dict[str, dict]:
    """The context passed to each template, keyed by template file name."""
    check_step(step)
    info = _check_info(info)
    head = header_lines(info)
    common = {"header_lines": head, "n": step.n, "d": step.d}
    return {
        "kernels.c.j2": dict(common, nz=step.nz, hash=info["hash"],
                             casadi_code=casadi_c_code(step, info["module"]),
                             kernels=[c_kernel_context(k) for k in step.kernels],
                             flatten=_step_instructions(step) <= FLATTEN_MAX_INSTRUCTIONS,
                             record_width=step.record_width,
                             open=None if step.open_spec is None else {
                                 "m": step.open_spec.m, "P": step.open_spec.P},
                             record_uses_xi=bool(step.record_uses_xi),
                             legendre_quadratic=bool(step.legendre_quadratic),
                             step_uses_g=bool(step.step_uses_g),
                             record_uses_g=bool(step.record_uses_g), **c_abi_context()),
        "kernels.py.j2": dict(common, nz=step.nz, module=info["module"],
                              **_python_linear(step.nz),
                              safe_unary=[list(p) for p in SAFE_UNARY],
                              kernels=[py_kernel_context(k) for k in step.kernels]),
        "__init__.py.j2": dict(common, module=info["module"], hash=info["hash"],
                               backend=info["backend"], model_label=_safe(info["model_name"]),
                               record_note=" (" + ", ".join(
                                   name for name, _, _ in step.record_layout) + ")"),
    }


def meta(step, info: dict) -> dict:
    """The content of meta.json (see the module docstring of hpgen.runtime.loader)."""
    info = _check_info(info)
    kernels = {}
    for k in step.kernels:
        f = k.function
        kernels[k.name] = {
            "inputs": [[k.inputs[i], int(f.numel_in(i))] for i in range(f.n_in())],
            "outputs": [[k.outputs[i], int(f.numel_out(i))] for i in range(f.n_out())],
            "instructions": int(f.n_instructions())}
    return {"format": abi.META_FORMAT, "hpgen_version": __version__, "module": info["module"],
            "model": info["model_name"], "options": info["options"], "hash": info["hash"],
            "backend": info["backend"], "n": step.n, "d": step.d, "nz": step.nz,
            "reduced": bool(step.reduced), "section": step.section,
            "legendre_quadratic": bool(step.legendre_quadratic),
            "record": [[name, int(off), [int(x) for x in shape]]
                       for name, off, shape in step.record_layout],
            "step_uses_g": bool(step.step_uses_g), "record_uses_g": bool(step.record_uses_g),
            "record_uses_xi": bool(step.record_uses_xi),
            "unknowns": [[str(u[0]), int(u[1]), int(u[2])] for u in step.unknowns],
            "kernels": kernels,
            "c_work": {k.name: work_sizes(k.function) for k in step.kernels},
            **_open_meta(step)}


def _open_meta(step) -> dict:
    """meta.json's "open" entry for an open model (absent for a closed one, whose meta.json
    is unchanged): the step vector's content (hpgen.abi.step_vector_size)."""
    spec = step.open_spec
    if spec is None:
        return {}
    return {"open": {"H": spec.H, "inputs": list(spec.inputs),
                     "runtime_parameters": [[name, [int(x) for x in shape]]
                                            for name, shape in spec.runtime_parameters],
                     "defaults": [float(v) for v in spec.defaults],
                     "forced": bool(spec.forced), "time_dependent": bool(spec.time_dependent)}}


def emit(step, info: dict) -> GeneratedModule:
    """Generate all files of one module; see the module docstring. Raises CodegenError."""
    checked = _check_info(info)
    env = environment()
    contexts = template_contexts(step, checked)
    rendered = {out: env.get_template(t).render(**contexts[t]) for out, t in TEMPLATES.items()}
    meta_text = json.dumps(meta(step, checked), sort_keys=True, indent=2) + "\n"
    files = (("__init__.py", rendered["__init__.py"]), ("kernels.c", rendered["kernels.c"]),
             ("kernels.py", rendered["kernels.py"]), ("meta.json", meta_text),
             ("model.yaml", checked["model_source"]))
    return GeneratedModule(name=checked["module"], files=files)

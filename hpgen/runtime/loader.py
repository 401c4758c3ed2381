"""load(): open a generated module directory as an Integrator.

meta.json (format hpgen.abi.META_FORMAT; any other is refused: recompile the module) holds:
format, hpgen_version, module, model, options {tableau, tau, rkmk}, hash, backend ("c" |
"python", the default), group (e.g. "SO3", "[SO3, R3]"), n, d, nz, reduced, section,
legendre_quadratic, record [[name, offset, shape], ...] (hpgen.abi.record_width), step_uses_g,
record_uses_g, record_uses_xi, unknowns [[label, start, stop], ...], kernels {name: {"inputs":
[[name, size], ...], "outputs": ..., "instructions": int}} (hpgen.abi.KERNELS), c_work
{name: {sz_arg, sz_res, sz_iw, sz_w}} and jacobian, the Newton matrix's storage: {"storage":
"dense"} or {"storage": "sparse", "colind": [nz + 1 ints], "row": [...]} (J's CCS pattern,
hpgen.codegen.sparse).
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

from .. import abi
from ..cache import check_sources
from ..errors import ModelError
from ..schemes import BACKENDS
from .backends import PythonBackend
from .cbackend import CBackend
from .integrator import Integrator

META_FORMAT = abi.META_FORMAT


def read_meta(module_dir) -> dict:
    """Read and validate meta.json; raises ModelError naming the file and field."""
    path = Path(module_dir) / "meta.json"
    try:
        meta = json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise ModelError(f"cannot read a generated module's meta.json ({exc}); "
                         "regenerate the module", file=str(path)) from None

    def bad(field, msg):
        return ModelError(msg + "; regenerate the module with this hpgen", file=str(path),
                          field=field)

    if not isinstance(meta, dict):
        raise bad("format", "expected a JSON object")
    if meta.get("format") != abi.META_FORMAT:
        raise ModelError(f"the module was generated for meta.json format "
                         f"{meta.get('format')!r}, this hpgen reads format {abi.META_FORMAT}; "
                         "recompile it (hpgen compile MODEL.yaml)", file=str(path),
                         field="format")
    for key in ("n", "d", "nz"):
        if not isinstance(meta.get(key), int) or meta[key] < 1:
            raise bad(key, "expected a positive integer")
    for key in ("module", "hash", "backend", "group"):
        if not isinstance(meta.get(key), str):
            raise bad(key, "expected a string")
    if not re.fullmatch(r"[0-9a-f]{16,128}", meta["hash"]):
        raise bad("hash", "expected 16 to 128 lowercase hex digits")
    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,127}", meta["module"]):
        raise bad("module", "expected an identifier")
    if meta["backend"] not in BACKENDS:
        raise bad("backend", f"expected one of {BACKENDS}")
    n, d, nz = meta["n"], meta["d"], meta["nz"]
    try:
        w = abi.record_width(meta.get("record"), n, d)
    except ValueError as exc:
        raise bad("record", str(exc)) from None
    for key in ("step_uses_g", "record_uses_g", "record_uses_xi", "legendre_quadratic"):
        if not isinstance(meta.get(key), bool):
            raise bad(key, "expected true or false")
    _jacobian_entry(meta.get("jacobian"), nz, bad)
    op = _open_entry(meta, bad)
    size = abi.sizes(n, d, nz, w, 1 if op is None else op["H"])
    kernels = meta.get("kernels")
    if not isinstance(kernels, dict) or set(kernels) != set(abi.KERNEL_NAMES):
        raise bad("kernels", f"expected the kernels {abi.KERNEL_NAMES}")
    for spec in abi.KERNELS:
        name, k = spec.name, kernels[spec.name]
        try:
            got = ([int(s) for _, s in k["inputs"]], [int(s) for _, s in k["outputs"]])
        except (KeyError, TypeError, ValueError):
            raise bad(f"kernels.{name}", "malformed signature") from None
        ins, outs = abi.signature(name, op is not None)
        want = ([size[s] for s in ins], [size[s] for s in outs])
        if got != want:
            raise bad(f"kernels.{name}", f"sizes {got} do not match the contract {want}")
    return meta


def _jacobian_entry(jac, nz: int, bad) -> None:
    """meta["jacobian"] checked: dense, or sparse with a CCS pattern of an nz x nz matrix."""
    if not isinstance(jac, dict) or jac.get("storage") not in ("dense", "sparse"):
        raise bad("jacobian", 'expected {"storage": "dense" | "sparse", ...}')
    if jac["storage"] == "dense":
        return
    colind, row = jac.get("colind"), jac.get("row")
    ok = (isinstance(colind, list) and isinstance(row, list) and len(colind) == nz + 1
          and all(isinstance(v, int) for v in colind + row) and colind[0] == 0
          and colind[-1] == len(row) and all(a <= b for a, b in zip(colind, colind[1:]))
          and all(0 <= r < nz for r in row))
    if not ok:
        raise bad("jacobian", f"expected colind ({nz + 1} nondecreasing ints from 0) and row "
                              f"(ints in [0, {nz}))")


def _open_entry(meta: dict, bad):
    """meta["open"] (an open model's step vector, hpgen.abi) checked, or None (closed)."""
    op = meta.get("open")
    if op is None:
        return None
    ok = (isinstance(op, dict) and isinstance(op.get("inputs"), list)
          and all(isinstance(u, str) for u in op["inputs"])
          and isinstance(op.get("runtime_parameters"), list)
          and isinstance(op.get("defaults"), list)
          and all(isinstance(v, (int, float)) for v in op["defaults"])
          and isinstance(op.get("forced"), bool) and isinstance(op.get("time_dependent"), bool))
    if ok:
        try:
            P = sum(math.prod(shape) for _, shape in op["runtime_parameters"])
        except (TypeError, ValueError):
            P = -1
        ok = P == len(op["defaults"]) and op.get("H") == abi.step_vector_size(
            len(op["inputs"]), P, True)
    if not ok:
        raise bad("open", "expected {H, inputs, runtime_parameters, defaults, forced, "
                          "time_dependent} consistent with H = 2 + m + P")
    return op


def load(path, backend=None, *, cc=None, cflags=None, compose=None) -> Integrator:
    """The Integrator of the generated module directory ``path``.

    backend: "c" (compile kernels.c once, load with ctypes) or "python" (import kernels.py
    from the directory); None = the module's default from meta.json. cc/cflags: see
    hpgen.runtime.build.build_library. compose: a composition's name
    (hpgen.tableaus.composition; None: the plain step) making every step the composed step of
    the module's symmetric scheme (the same kernels). A directory with a MANIFEST.json (``hpgen compile -o``
    output) is checked against it first. Raises ModelError (bad directory or backend, sources
    that differ from their recorded digests) and
    BuildError (compiler missing or failing; backend="python" needs no compiler).
    """
    module_dir = Path(path)
    meta = read_meta(module_dir)
    backend = meta["backend"] if backend is None else backend
    if backend == "python":
        check_sources(module_dir)     # the C backend's build_library checks them too
        if not (module_dir / "kernels.py").is_file():
            raise ModelError("the module has no kernels.py (it was compiled for the C backend "
                             "only); compile it with backend='python' (hpgen compile "
                             "--backend python), which writes it", file=str(module_dir))
    impl: CBackend | PythonBackend
    if backend == "c":
        impl = CBackend(module_dir, meta, cc=cc, cflags=cflags)
    elif backend == "python":
        impl = PythonBackend(module_dir, meta)
    else:
        raise ModelError(f"unknown backend {backend!r}; expected one of {BACKENDS}",
                         field="backend")
    composition = None
    if compose is not None:
        from ..tableaus.composition import check_base, get_composition
        composition = get_composition(compose)
        check_base(meta["options"]["tableau"], rkmk=meta["options"]["rkmk"],
                   step_uses_g=meta["step_uses_g"], explicit=meta.get("explicit") is True)
        impl.compose = composition.gammas
    return Integrator(meta, impl, module_dir, composition)

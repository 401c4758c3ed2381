"""The compile entry point: model file + options -> cached generated module -> Integrator.

    integ = hpgen.compile("examples/heavy_top.yaml", tableau="gauss2", tau="exp",
                          rkmk="exact", backend="c", out="generated/")

Options left as None take the model's ``integrator:`` defaults. The cache key hashes the
model file's bytes, the explicit options and the hpgen version, so a cache hit imports
nothing of the compile-time stack (sympy, casadi, jinja2).

``build`` is the same compile returning what it produced (a CompiledModule: the module
directory, its meta.json, whether the cache served it, and the derivation: model, resolved
tableau/tau/rkmk and DiscreteStep), so that consumers (hpgen check, hpgen bench) reuse it
instead of resolving, deriving or locating cache entries again.
"""
from __future__ import annotations

import dataclasses
import hashlib
import json
from dataclasses import dataclass
from functools import cached_property, lru_cache
from pathlib import Path
from typing import Any

from . import __version__, cache
from .errors import ModelError
#: the option values (re-exported: hpgen.bench reads TAU_CHOICES, RKMK_CHOICES from here)
from .schemes import BACKEND, BACKENDS, RKMK, RKMK_CHOICES, TAU, TAU_CHOICES  # noqa: F401

#: bump when the generated layout changes, so stale cache entries are not reused
CODE_FORMAT = "1"


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

    def validate(self):
        for option, value in ((TAU, self.tau), (RKMK, self.rkmk), (BACKEND, self.backend)):
            if value is not None:
                option.check(value, field=f"option {option.name}")
        if self.tableau is not None and not isinstance(self.tableau, (str, dict)) \
                and not hasattr(self.tableau, "A"):
            raise ModelError("expected a catalog name or {A: [[...]], b: [...]}",
                             field="option tableau")

    def key(self) -> str:
        """The part of the cache key that the options contribute (code-changing only)."""
        tab = self.tableau
        if tab is not None and not isinstance(tab, (str, dict)):
            tab = {"A": [list(r) for r in tab.A], "b": list(tab.b), "name": tab.name}
        return json.dumps({"tableau": tab, "tau": self.tau, "rkmk": self.rkmk},
                          sort_keys=True, default=repr)


def read_model_text(path) -> str:
    try:
        data = Path(path).read_bytes()
    except OSError as e:
        raise ModelError(f"cannot read the model file ({e.strerror})", file=str(path)) from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise ModelError("expected a UTF-8 text file", file=str(path)) from None


@dataclass(frozen=True)
class Derivation:
    """The derive stage's result for one compile: the parsed model, the resolved tableau
    (a ButcherTableau), tau and rkmk, and the DiscreteStep."""
    model: Any
    tableau: Any
    tau: str
    rkmk: str
    step: Any


@dataclass(frozen=True, eq=False)
class CompiledModule:
    """What one compile produced.

    source: the model file; text: its text as compiled; options: the CompileOptions;
    module_dir: the generated module's directory; meta: its meta.json; cached: the module's
    sources came from the build cache (nothing was derived); built: this compile ran the C
    compiler (backend "c"). ``derivation`` is this compile's Derivation, or on a cache hit
    the same one derived on first access (the compile-time stack is imported only then).
    """
    source: str
    text: str
    options: "CompileOptions"
    module_dir: Path
    meta: dict
    cached: bool
    built: bool = False
    derived: Derivation | None = None

    @cached_property
    def derivation(self) -> Derivation:
        return self.derived if self.derived is not None else derive_module(
            self.source, self.text, self.options)

    def load(self, backend=None):
        """The runtime Integrator of the module (backend None: the compile's backend)."""
        from .runtime import load
        o = self.options
        return load(self.module_dir, backend=o.backend if backend is None else backend,
                    cc=o.cc, cflags=o.cflags)


def compile(model, *, tableau=None, tau=None, rkmk=None, backend="c", out=None,
            cache_dir=None, cc=None, cflags=None):
    """Compile ``model`` (a path to a model file) and return a loaded runtime Integrator
    (``build(...).load()``)."""
    return build(model, tableau=tableau, tau=tau, rkmk=rkmk, backend=backend, out=out,
                 cache_dir=cache_dir, cc=cc, cflags=cflags).load()


def build(model, *, tableau=None, tau=None, rkmk=None, backend="c", out=None,
          cache_dir=None, cc=None, cflags=None) -> CompiledModule:
    """Compile ``model`` like ``compile`` and return the CompiledModule (not loaded)."""
    return build_compiled(model, CompileOptions(tableau, tau, rkmk, backend, out, cache_dir,
                                                cc, tuple(cflags) if cflags else None))


#: what produces the generated code, besides the model and options (hashed into the key)
_GENERATOR_SOURCES = ("hpgen/abi.py", "hpgen/model", "hpgen/groups", "hpgen/tableaus",
                      "hpgen/derive", "hpgen/codegen", "templates")


@lru_cache(maxsize=1)
def generator_digest() -> str:
    """sha256 over hpgen's code-generating sources (stages and templates), so that a
    changed generator never serves a stale cache entry."""
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for source in _GENERATOR_SOURCES:
        path = root / source
        for f in [path] if path.is_file() else sorted(path.glob("*")):
            if f.is_file() and f.suffix in (".py", ".j2"):
                h.update(f.relative_to(root).as_posix().encode() + b"\0" + f.read_bytes())
    return h.hexdigest()


def module_key(text: str, opts: CompileOptions) -> str:
    """Cache key and content hash of a module: model text, code-changing options, hpgen
    version and generator sources."""
    return cache.cache_key(CODE_FORMAT, __version__, generator_digest(), text, opts.key())


def build_module(model, opts: CompileOptions) -> Path:
    """Generate (or fetch from the cache) the module for ``model``; return its directory."""
    return build_compiled(model, opts).module_dir


def build_compiled(model, opts: CompileOptions) -> CompiledModule:
    """Generate (or fetch from the cache) the module for ``model``, build its C library
    (backend "c"), copy it to opts.out if given; return the CompiledModule."""
    opts.validate()
    text = read_model_text(model)
    cache_dir = Path(opts.cache_dir) if opts.cache_dir else cache.default_cache_dir()
    key = module_key(text, opts)
    entry = cache_dir / key
    derived = None
    if not cache.is_valid(entry):
        with cache.locked(cache_dir, key):
            if not cache.is_valid(entry):
                derived = derive_module(str(model), text, opts)
                cache.write_tree(entry, emit_files(derived, text, opts, key))
    meta = json.loads((entry / "meta.json").read_text())
    built = False
    if opts.backend == "c":
        from .runtime.build import build_library, library_name
        built = not (entry / library_name(meta["hash"], opts.cflags)).exists()
        build_library(entry, cc=opts.cc, cflags=opts.cflags)
    result = CompiledModule(str(model), text, opts, entry, meta, cached=derived is None,
                            built=built, derived=derived)
    if opts.out is None:
        return result
    files = cache.read_tree(entry)
    files.update({p.name: p.read_bytes() for p in entry.glob("_kernels_*.so")})
    dest = Path(opts.out) / meta["module"]
    if not _same_tree(dest, files):
        cache.write_tree(dest, files, manifest=False)
    return dataclasses.replace(result, module_dir=dest)


def _same_tree(dest: Path, files: dict) -> bool:
    try:
        return all((dest / name).read_bytes() == data for name, data in files.items())
    except OSError:
        return False


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


def generate_files(path: str, text: str, opts: CompileOptions, key: str) -> dict[str, str]:
    """Run the pipeline model -> derive -> codegen; the files of the generated module."""
    return emit_files(derive_module(path, text, opts), text, opts, key)


def derive_module(path: str, text: str, opts: CompileOptions) -> Derivation:
    """The model (text of the file ``path``) parsed, its options resolved and its step
    derived and checked. Raises ModelError naming the file."""
    from .model import load_model_text

    model_obj = load_model_text(text, filename=path)   # bad input fails before casadi loads
    from .derive import derive
    from .derive.checks import check_legendre
    try:
        tab, tau, rkmk = resolve(model_obj, opts)
        step = derive(model_obj, tab, tau, rkmk)
        check_legendre(step, model_obj)
    except ModelError as e:          # errors of the options and the derivation name the file too
        raise e.located(file=path) from None
    return Derivation(model_obj, tab, tau, rkmk, step)


def emit_files(d: Derivation, text: str, opts: CompileOptions, key: str) -> dict[str, str]:
    """The files of the generated module of a derivation (codegen)."""
    from .codegen import emit, module_name
    name = module_name(d.model.name, d.tableau.name, d.tau, d.rkmk)
    gm = emit(d.step, {"module": name, "model_name": d.model.name, "model_source": text,
                       "options": {"tableau": d.tableau.name, "tau": d.tau, "rkmk": d.rkmk},
                       "hash": key, "backend": opts.backend})
    return dict(gm.files)

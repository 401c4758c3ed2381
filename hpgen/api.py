"""The compile entry point: model file + options -> cached generated module -> Integrator.

    integ = hpgen.compile("examples/heavy_top.yaml", tableau="gauss2", tau="exp",
                          rkmk="exact", backend="c", out="generated/")

Options left as None take the model's ``integrator:`` defaults. The cache key hashes the
model file's bytes, the explicit options and the hpgen version, so a cache hit imports
nothing of the compile-time stack (sympy, casadi, jinja2).
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

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


def compile(model, *, tableau=None, tau=None, rkmk=None, backend="c", out=None,
            cache_dir=None, cc=None, cflags=None):
    """Compile ``model`` (a path to a model file) and return a loaded runtime Integrator."""
    opts = CompileOptions(tableau, tau, rkmk, backend, out, cache_dir, cc,
                          tuple(cflags) if cflags else None)
    module_dir = build_module(model, opts)
    from .runtime import load
    return load(module_dir, backend=opts.backend, cc=opts.cc, cflags=opts.cflags)


#: what produces the generated code, besides the model and options (hashed into the key)
_GENERATOR_SOURCES = ("hpgen/model", "hpgen/groups", "hpgen/tableaus", "hpgen/derive",
                      "hpgen/codegen", "templates")


@lru_cache(maxsize=1)
def generator_digest() -> str:
    """sha256 over hpgen's code-generating sources (stages and templates), so that a
    changed generator never serves a stale cache entry."""
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for folder in _GENERATOR_SOURCES:
        for f in sorted((root / folder).glob("*")):
            if f.is_file() and f.suffix in (".py", ".j2"):
                h.update(f"{folder}/{f.name}".encode() + b"\0" + f.read_bytes())
    return h.hexdigest()


def module_key(text: str, opts: CompileOptions) -> str:
    """Cache key and content hash of a module: model text, code-changing options, hpgen
    version and generator sources."""
    return cache.cache_key(CODE_FORMAT, __version__, generator_digest(), text, opts.key())


def build_module(model, opts: CompileOptions) -> Path:
    """Generate (or fetch from the cache) the module for ``model``; return its directory."""
    opts.validate()
    text = read_model_text(model)
    cache_dir = Path(opts.cache_dir) if opts.cache_dir else cache.default_cache_dir()
    key = module_key(text, opts)
    entry = cache_dir / key
    if not cache.is_valid(entry):
        with cache.locked(cache_dir, key):
            if not cache.is_valid(entry):
                files = generate_files(str(model), text, opts, key)
                cache.write_tree(entry, files)
    meta = json.loads((entry / "meta.json").read_text())
    if opts.backend == "c":
        from .runtime.build import build_library
        build_library(entry, cc=opts.cc, cflags=opts.cflags)
    if opts.out is None:
        return entry
    files = cache.read_tree(entry)
    files.update({p.name: p.read_bytes() for p in entry.glob("_kernels_*.so")})
    dest = Path(opts.out) / meta["module"]
    if not _same_tree(dest, files):
        cache.write_tree(dest, files, manifest=False)
    return dest


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
    from .model import load_model_text

    model_obj = load_model_text(text, filename=path)   # bad input fails before casadi loads
    from .codegen import emit, module_name
    from .derive import derive
    from .derive.checks import check_legendre
    try:
        tab, tau, rkmk = resolve(model_obj, opts)
        step = derive(model_obj, tab, tau, rkmk)
        check_legendre(step, model_obj)
    except ModelError as e:          # errors of the options and the derivation name the file too
        raise e.located(file=path) from None
    name = module_name(model_obj.name, tab.name, tau, rkmk)
    gm = emit(step, {"module": name, "model_name": model_obj.name, "model_source": text,
                     "options": {"tableau": tab.name, "tau": tau, "rkmk": rkmk},
                     "hash": key, "backend": opts.backend})
    return dict(gm.files)

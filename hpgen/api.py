"""The compile entry point: model file + options -> cached generated module -> Integrator.

    integ = hpgen.compile("examples/heavy_top.yaml", tableau="gauss2", tau="exp",
                          rkmk="exact", backend="c", out="generated/")

Options left as None take the model's ``integrator:`` defaults.

The cache has two levels (content-addressed, as pystencils and FFCx do):
- the *content hash* (``content_hash``) is the sha256 of what the generated code is a
  function of: the normalized model (hpgen.model.fingerprint: group, Lagrangian, parameters,
  the scene's record and section; not comments, formatting, h, steps or the initial state),
  the options in effect (tableau with a user's A/b, tau, rkmk), CODE_FORMAT and the hpgen
  version. It is the hash written into every generated file's header, meta.json and
  ``hpgen_hash()``: the same hash means the same model and options, whichever generator
  revision emitted the files;
- the *derivation key* (``module_key``, the cache entry's name) adds the digest of the
  generator's sources, so an edited generator derives again;
- the C library is keyed by the sha256 of the emitted kernels.c plus compiler and flags
  (hpgen.runtime.build), so a derivation that emits the same C reuses the built library.
A cache hit imports nothing of the compile-time stack (sympy, casadi, jinja2).

An entry holds the sources of the backends compiled so far (BACKEND_SOURCES): a C compile
writes kernels.c, not kernels.py; the first compile for the other backend derives again and
adds its source to the entry (hpgen.cache.add_files); ``out`` copies get both.

``build`` is the same compile returning what it produced (a CompiledModule: the module
directory, its meta.json, whether the cache served it, and the derivation: model, resolved
tableau/tau/rkmk and DiscreteStep), so that consumers (hpgen check, hpgen bench) reuse it
instead of resolving, deriving or locating cache entries again.
"""
from __future__ import annotations

import dataclasses
import json
import sys
import time
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

from . import cache
from .compile_options import CompileOptions, model_source, read_model_text, resolve
from .errors import ModelError
from .module_hash import CODE_FORMAT, content_hash, generator_digest
from .pipeline import BACKEND_SOURCES, Derivation, derive_module, emit_files, generate_files

__all__ = ["BACKEND_SOURCES", "CODE_FORMAT", "CompileOptions", "CompiledModule", "Derivation",
           "build", "build_compiled", "build_module", "compile", "content_hash",
           "derive_module", "emit_files", "generate_files", "generator_digest",
           "model_source", "module_key", "read_model_text", "resolve"]


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
    #: the composition the module is loaded with (the option's, else the model file's)
    compose: str | None = None
    #: seconds this compile spent per stage ("derive", "emit", "write", "cc"; a stage that
    #: did not run is absent)
    timings: Mapping[str, float] = dataclasses.field(default_factory=dict)

    @cached_property
    def derivation(self) -> Derivation:
        return self.derived if self.derived is not None else derive_module(
            self.source, self.text, self.options)

    def load(self, backend=None):
        """The runtime Integrator of the module (backend None: the compile's backend). A
        cache entry compiled for one backend gets the other's source on first use."""
        from .runtime import load
        o = self.options
        backend = o.backend if backend is None else backend
        if backend != o.backend and not cache.has_files(self.module_dir,
                                                        (BACKEND_SOURCES[backend],)):
            cache_dir = self.module_dir.parent
            with cache.locked(cache_dir, self.module_dir.name):
                _add_sources(self.module_dir, self.source, self.text, self.options,
                             (BACKEND_SOURCES[backend],), {})
        return load(self.module_dir, backend=backend, cc=o.cc, cflags=o.cflags,
                    compose=self.compose)


def compile(model, *, tableau=None, tau=None, rkmk=None, backend="c", out=None,
            cache_dir=None, cc=None, cflags=None, parameters=None, jacobian=None,
            compose=None):
    """Compile a model (a model file, or one declared in Python) into an integrator and load it.

    The module is generated (or taken from the build cache), built (C backend) and loaded.
    A cache hit imports none of sympy, casadi, jinja2.

    Parameters
    ----------
    model : str, pathlib.Path, mapping or hpgen.model.builder.ModelBuilder
        Path of the model file (YAML, docs/model-file.md); or a mapping with the model
        file's keys, or a ModelBuilder (SymPy expressions), checked by the same rules and
        compiled into the module of the equivalent file (hpgen.model.builder).
    tableau : str, dict, ButcherTableau or None, optional
        Catalog name (``euler-forward``, ``euler-backward``, ``stormer-verlet``, ``midpoint``,
        ``gauss2``, ``gauss3``, ``lobatto3a3``; ``hpgen list``), or a user tableau
        ``{"A": [[...]], "b": [...]}`` (optional ``"c"``; every b_j != 0). None: the
        model's ``integrator.tableau``, else ``stormer-verlet``.
    tau : {"exp", "cay", "skew"} or None, optional
        Chart map (``skew`` on SO2 and SO3 only). None: the model's, else ``cay``.
    rkmk : {"exact", "truncated"} or None, optional
        RKMK constraint: ``exact`` keeps the tableau's order, ``truncated`` is the paper's
        q = 0 (order <= 2). None: the model's, else ``exact``.
    backend : {"c", "python"}, optional
        ``c`` (default) builds the kernels with the C compiler; ``python`` needs no compiler
        and gives bitwise the same states for up to 12 unknowns.
    out : str, pathlib.Path or None, optional
        Directory that receives a copy of the module as ``<out>/<module>/`` (importable on
        its own with numpy and hpgen.runtime). None (default): load from the cache entry.
    cache_dir : str, pathlib.Path or None, optional
        Build cache directory. None: ``$XDG_CACHE_HOME/hpgen``, else ``~/.cache/hpgen``.
    cc : str or None, optional
        C compiler command (may include arguments). None: ``$CC``, else ``cc``.
    cflags : sequence of str or None, optional
        Extra compiler flags after the defaults ``-std=c99 -O3 -fPIC -shared`` (a library
        built with extra flags is kept apart from the portable one).
    parameters : dict or None, optional
        New values of parameters declared in the file, e.g. ``{"N": 8}`` (a family's body
        count): the model is the file with these values (a different module, cached apart).
    jacobian : {"sparse", "dense"} or None, optional
        How Newton stores and factors the step's Jacobian: dense LU, or a sparse QR on its
        structural nonzeros. None (default): sparse for large, sparse systems
        (hpgen.derive.sparse_jacobian).
    compose : str or None, optional
        A composition of the module's symmetric step (``yoshida4``, ``suzuki4``,
        ``yoshida6``, ``kahan-li6``; ``hpgen list``): every step is S(gamma_s h) o ... o
        S(gamma_1 h) of the same compiled kernels (docs/numerics.md). None: the model's
        ``integrator.compose``, else the plain step. Refused for a non-symmetric scheme.

    Returns
    -------
    hpgen.runtime.integrator.Integrator
        The loaded integrator (``step``, ``simulate``, ``stream``, ``record``, ``sections``,
        ``simulate_batch``, ...; docs/api.md).

    Raises
    ------
    ModelError
        Bad model file or option (one line: file, line, field, what was expected).
    BuildError
        The C compiler is missing or failed (``backend="python"`` is the fallback).
    """
    return build(model, tableau=tableau, tau=tau, rkmk=rkmk, backend=backend, out=out,
                 cache_dir=cache_dir, cc=cc, cflags=cflags, parameters=parameters,
                 jacobian=jacobian, compose=compose).load()


def build(model, *, tableau=None, tau=None, rkmk=None, backend="c", out=None,
          cache_dir=None, cc=None, cflags=None, parameters=None,
          jacobian=None, compose=None) -> CompiledModule:
    """Compile ``model`` like ``compile`` and return the CompiledModule (not loaded)."""
    return build_compiled(model, CompileOptions(tableau, tau, rkmk, backend, out, cache_dir,
                                                cc, tuple(cflags) if cflags else None,
                                                tuple(dict(parameters).items())
                                                if parameters else None, jacobian, compose))


def module_key(text: str, opts: CompileOptions) -> str:
    """The derivation key (the cache entry's name): the content hash and the digest of the
    generator's sources."""
    return _derivation_key(content_hash(text, opts))


def _derivation_key(chash: str) -> str:
    return cache.cache_key(chash, generator_digest())


def build_module(model, opts: CompileOptions) -> Path:
    """Generate (or fetch from the cache) the module for ``model``; return its directory."""
    return build_compiled(model, opts).module_dir


def build_compiled(model, opts: CompileOptions) -> CompiledModule:
    """Generate (or fetch from the cache) the module for ``model``, build its C library
    (backend "c"); return the CompiledModule.

    With ``opts.out`` the module (sources, MANIFEST.json, this request's model file and, for
    the C backend, the checked library) is copied to ``<out>/<module>/``. A cache directory
    that cannot be written is reported in one line on stderr and a private temporary cache
    is used instead.
    """
    opts.validate()
    source, text = model_source(model)
    if opts.parameters:
        from .model.overrides import apply_overrides
        text = apply_overrides(text, dict(opts.parameters), file=source)
    cache_dir = Path(opts.cache_dir) if opts.cache_dir else cache.default_cache_dir()
    try:
        result, library = _cached_module(source, text, opts, cache_dir)
    except cache.CacheUnwritable as exc:
        tmp = cache.private_cache_dir()
        print(f"hpgen: warning: the cache directory {cache_dir} cannot be written "
              f"({exc.reason}); building in {tmp}", file=sys.stderr)
        result, library = _cached_module(source, text, opts, tmp)
    result = dataclasses.replace(result, compose=_compose_of(text, opts))
    if opts.out is None:
        return result
    entry = result.module_dir
    files: dict[str, bytes | str] = dict(cache.read_tree(entry))
    files["model.yaml"] = text.encode()      # this request's file (the entry keeps the first)
    unlisted = {}
    if library is not None:
        from .runtime.build import read_library
        unlisted[library.name], unlisted[library.name + ".json"] = read_library(library)
    dest = Path(opts.out) / result.meta["module"]
    if not (_same_tree(dest, {**files, **unlisted}) and cache.is_valid(dest)):
        try:
            cache.write_tree(dest, files, unlisted=unlisted)
        except OSError as exc:
            raise ModelError(f"cannot write the module to {dest} ({exc.strerror or exc})",
                             field="option out") from None
    return dataclasses.replace(result, module_dir=dest)


def _compose_of(text: str, opts: CompileOptions) -> str | None:
    """The composition in effect: the option's, else the model file's integrator.compose
    (checked by the model loader when the module was derived)."""
    if opts.compose is not None:
        return opts.compose
    from .model.fingerprint import normalized_model
    written = normalized_model(text)[1]
    return written.get("compose") if isinstance(written, dict) else None


def _needed_sources(opts: CompileOptions) -> tuple[str, ...]:
    """The backend sources a compile needs: its backend's, both when it copies the module
    out (``-o``: a module directory loadable with either backend)."""
    if opts.out is not None:
        return tuple(BACKEND_SOURCES.values())
    return (BACKEND_SOURCES[opts.backend],)


def _cached_module(path: str, text: str, opts: CompileOptions, cache_dir: Path):
    """(CompiledModule of the cache entry, built library or None) of one compile;
    CacheUnwritable when the cache directory cannot be written and something is missing
    from it."""
    chash = content_hash(text, opts)
    key = _derivation_key(chash)
    entry = cache_dir / key
    derived = None
    timings: dict[str, float] = {}
    need = _needed_sources(opts)
    if not cache.has_files(entry, need):
        with cache.locked(cache_dir, key):
            if not cache.is_valid(entry):
                derived = _timed(timings, "derive", derive_module, path, text, opts)
                files = _timed(timings, "emit", emit_files, derived, text, opts, chash,
                               sources=need)
                try:
                    _timed(timings, "write", cache.write_tree, entry, files)
                except OSError as exc:
                    raise cache.CacheUnwritable(cache_dir, exc) from None
            elif not cache.has_files(entry, need):
                derived = _add_sources(entry, path, text, opts, need, timings)
    meta = json.loads((entry / "meta.json").read_text())
    library, built = None, False
    if opts.backend == "c":
        from .runtime.build import build_library, find_library
        built = find_library(entry, cc=opts.cc, cflags=opts.cflags) is None
        library = _timed(timings, "cc", build_library, entry, cc=opts.cc, cflags=opts.cflags,
                         store=cache.library_store(cache_dir))
        if not built:
            del timings["cc"]
    return CompiledModule(path, text, opts, entry, meta, cached=derived is None,
                          built=built, derived=derived, timings=timings), library


def _add_sources(entry: Path, path: str, text: str, opts: CompileOptions, need, timings):
    """Derive again and add the backend sources ``need`` that the valid entry lacks (each
    file atomically, listed in its manifest last); the caller holds the entry's lock.
    Returns the Derivation."""
    missing = tuple(name for name in need if not cache.has_files(entry, (name,)))
    derived = _timed(timings, "derive", derive_module, path, text, opts)
    files = _timed(timings, "emit", emit_files, derived, text, opts,
                   content_hash(text, opts), sources=missing)
    try:
        _timed(timings, "write", cache.add_files, entry,
               {name: files[name] for name in missing})
    except OSError as exc:
        raise cache.CacheUnwritable(entry.parent, exc) from None
    return derived


def _timed(timings: dict, stage: str, fn, *args, **kw):
    """fn(*args, **kw), its wall time added to timings[stage]."""
    t0 = time.perf_counter()
    try:
        return fn(*args, **kw)
    finally:
        timings[stage] = timings.get(stage, 0.0) + time.perf_counter() - t0


def _same_tree(dest: Path, files: dict) -> bool:
    try:
        return all((dest / name).read_bytes() == data for name, data in files.items())
    except OSError:
        return False

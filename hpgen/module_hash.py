"""The content hash of a generated module and the digest of the generator's sources
(hpgen.api's module docstring: the two levels of the build cache's keys)."""
from __future__ import annotations

import hashlib
import json
from functools import lru_cache
from pathlib import Path

from . import __version__, cache
from .compile_options import CompileOptions

#: bump when the generated layout changes, so stale cache entries are not reused
CODE_FORMAT = "1"


#: what produces the generated code, besides the model and options (hashed into the key)
_GENERATOR_SOURCES = ("hpgen/abi.py", "hpgen/model", "hpgen/groups", "hpgen/tableaus",
                      "hpgen/derive", "hpgen/splitting", "hpgen/codegen", "templates")


@lru_cache(maxsize=1)
def generator_digest() -> str:
    """sha256 over hpgen's code-generating sources (stages and templates), so that a
    changed generator never serves a stale cache entry."""
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for source in _GENERATOR_SOURCES:
        path = root / source
        if source == "templates" and (root / "hpgen" / "templates").is_dir():
            path = root / "hpgen" / "templates"      # a wheel ships them inside the package
        for f in [path] if path.is_file() else sorted(path.glob("*")):
            if f.is_file() and f.suffix in (".py", ".j2"):
                h.update(f.relative_to(root).as_posix().encode() + b"\0" + f.read_bytes())
    return h.hexdigest()


def content_hash(text: str, opts: CompileOptions) -> str:
    """The content hash of a module (see the module docstring): normalized model, options
    in effect, CODE_FORMAT and hpgen version; never the generator's sources."""
    from .model.fingerprint import normalized_model
    from .model.types import IntegratorChoice
    norm, written = normalized_model(text)
    if isinstance(written, dict) and "compose" in written:   # runtime only: not in the key
        written = {k: v for k, v in written.items() if k != "compose"} or None
    written_opts = written if isinstance(written, dict) else {}
    effective = {k: next((v for v in (getattr(opts, k), written_opts.get(k),
                                      getattr(IntegratorChoice(), k)) if v is not None))
                 for k in ("tableau", "tau", "rkmk")}
    effective["jacobian"] = opts.jacobian
    model = json.dumps({"model": norm, "integrator": written}, sort_keys=True, default=repr)
    return cache.cache_key(CODE_FORMAT, __version__, model,
                           CompileOptions(**effective).key())

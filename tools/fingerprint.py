"""SHA-256 fingerprints of every run kind on the shipped scenes, both backends.

For refactors that must leave every number bitwise unchanged: run it before and after and
diff the two outputs (one line per model, backend and run kind: digest of every array,
iteration count and error the run returns).

    python tools/fingerprint.py > before.txt   # on the old tree
    python tools/fingerprint.py > after.txt    # on the new tree
    diff before.txt after.txt                  # empty: bitwise unchanged

``--skip NAME[,NAME]``: leave out the dataclass fields and dict keys of those names (to
compare across a change that adds a field, e.g. ``--skip guarded`` on the new tree against
a tree without it; a field the old tree lacks is then absent on both sides).
"""
from __future__ import annotations

import dataclasses
import hashlib
import sys
from pathlib import Path

import numpy as np

import hpgen
from hpgen.model import load_model

ROOT = Path(__file__).resolve().parent.parent
#: (example, compile options): every shipped scene with its default scheme, and the heavy
#: top with the other schemes the speed figures use
CASES = [(p.name, {}) for p in sorted((ROOT / "examples").glob("*.yaml"))] + [
    ("heavy_top.yaml", {"tableau": "stormer-verlet", "tau": "cay", "rkmk": "exact"}),
    ("heavy_top.yaml", {"tableau": "gauss3", "tau": "cay", "rkmk": "exact"}),
    ("free_rigid_body.yaml", {"tableau": "gauss2", "tau": "exp", "rkmk": "exact"}),
]
STEPS, EVERY, CHUNK, B = 60, 3, 17, 3
#: field and key names left out of the digests (--skip)
SKIP: set = set()


def digest(obj, h=None) -> str:
    """Digest of a run's result: arrays (dtype, shape, bytes), numbers, strings, errors, and
    the fields of dataclasses and dicts, recursively."""
    top = h is None
    h = h or hashlib.sha256()
    if isinstance(obj, np.ndarray):
        a = np.ascontiguousarray(obj)
        h.update(f"{a.dtype}{a.shape}".encode())
        h.update(a.tobytes())
    elif isinstance(obj, BaseException):
        h.update(f"{type(obj).__name__}:{obj}".encode())
        digest(getattr(obj, "partial", None), h)
    elif dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            v = getattr(obj, f.name)
            if f.name in SKIP:
                continue
            if isinstance(v, BaseException):      # the error whose .partial this is
                h.update(f"{f.name}:{type(v).__name__}:{v}".encode())
            elif f.compare:
                h.update(f.name.encode())
                digest(v, h)
    elif isinstance(obj, dict):
        for k in sorted((k for k in obj if str(k) not in SKIP), key=str):
            h.update(str(k).encode())
            digest(obj[k], h)
    elif isinstance(obj, (list, tuple)):
        h.update(f"seq{len(obj)}".encode())
        for x in obj:
            digest(x, h)
    else:
        h.update(repr(obj).encode())
    return h.hexdigest()[:16] if top else ""


def runs(integ, scene, model):
    """(kind, callable) of every run kind that applies to this module."""
    g0, h = scene.g0, scene.h
    x0 = {"xi0": scene.xi0} if scene.xi0 is not None else {"mu0": scene.mu0}
    ini = np.asarray(scene.xi0 if scene.xi0 is not None else scene.mu0, dtype=float)
    key = "xi0" if scene.xi0 is not None else "mu0"
    batch = {key: np.stack([ini * (1 + 0.01 * b) for b in range(B)])}
    kw = {}
    if integ.open and integ.open.get("inputs"):
        kw["u"] = np.zeros(len(integ.open["inputs"]))
    c = integ.backend == "c"
    out = [
        ("step", lambda: integ.step(g0, integ.legendre(g0, ini) if key == "xi0" else ini, h,
                                    **kw)),
        ("simulate", lambda: integ.simulate(g0, h, STEPS, every=EVERY, **x0, **kw)),
        ("simulate_every1", lambda: integ.simulate(g0, h, STEPS, **x0, **kw)),
        ("stream", lambda: list(integ.stream(g0, h, STEPS, every=EVERY, chunk=CHUNK, **x0,
                                             **kw))),
        ("record", lambda: integ.record(g0, h, STEPS, every=EVERY, **x0, **kw)),
        ("stream_record", lambda: list(integ.stream_record(g0, h, STEPS, every=EVERY,
                                                           chunk=CHUNK, **x0, **kw))),
        ("backward", lambda: integ.simulate(g0, -h, STEPS, every=EVERY, **x0, **kw)),
    ]
    if c:
        out += [
            ("simulate_batch", lambda: integ.simulate_batch(g0, h, STEPS, every=EVERY,
                                                            threads=2, **batch, **kw)),
            ("simulate_batch_nolanes", lambda: integ.simulate_batch(
                g0, h, STEPS, every=EVERY, threads=1, lanes=False, **batch, **kw)),
            ("record_batch", lambda: integ.record_batch(g0, h, STEPS, every=EVERY, threads=2,
                                                        **batch, **kw)),
        ]
    if scene.section is not None:
        out += [("sections", lambda: integ.sections(g0, h, 40 * STEPS, chunk=7 * CHUNK, **x0,
                                                    **kw)),
                ("sections_batch", lambda: integ.sections_batch(g0, h, 40 * STEPS, threads=2,
                                                                **batch, **kw))]
    if scene.section_every_t is not None:
        out += [("stroboscopic", lambda: integ.sections(
            g0, h, 300, every_t=scene.section_every_t, **x0, **kw))]

    def lin():
        tr = integ.simulate(g0, h, 8, **x0, **kw)
        return integ.linearize(tr, **kw)
    out.append(("linearize", lin))
    return out


def main() -> int:
    if "--skip" in sys.argv:
        SKIP.update(sys.argv[sys.argv.index("--skip") + 1].split(","))
    for name, opts in CASES:
        path = str(ROOT / "examples" / name)
        model = load_model(path)
        for backend in ("c", "python"):
            integ = hpgen.compile(path, backend=backend, **opts)
            tag = f"{integ.meta['module']}/{backend}"
            for kind, run in runs(integ, model.scene, model):
                try:
                    r = run()
                except hpgen.HpgenError as e:
                    r = e
                print(f"{tag} {kind} {digest(r)}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

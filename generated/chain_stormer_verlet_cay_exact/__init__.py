# hpgen generated module chain_stormer_verlet_cay_exact -- do not edit, regenerate with hpgen
# model: chain
# options: tableau=stormer-verlet, tau=cay, rkmk=exact
# hpgen version: 0.1.0
# content hash (normalized model + options): a2dfb8b7ac4b7bb6b25c1202570a7dfa27dfc11ad66e90e4a91132dd0bbacd79
"""hpgen integrator chain_stormer_verlet_cay_exact for the model chain.

Importing this package has no side effects; the first call of integrator(), step() or
simulate() loads it through hpgen.runtime (needs numpy only) and, for the C backend
(the default), compiles kernels.c once into this directory.
Group: n x n = 8 x 8 matrices, algebra dimension d = 12; g is passed as an
(n, n) array, momenta and velocities as length-d arrays, h in the model's time unit.
"""
import threading as _threading
from pathlib import Path as _Path

MODULE = "chain_stormer_verlet_cay_exact"
HASH = "a2dfb8b7ac4b7bb6b25c1202570a7dfa27dfc11ad66e90e4a91132dd0bbacd79"
BACKEND = "c"
_lock = _threading.Lock()
_loaded = {}


def integrator(backend=None):
    """The hpgen.runtime.Integrator of this module, "c" or "python" (None = BACKEND);
    loaded on first use and cached per backend."""
    backend = BACKEND if backend is None else backend
    with _lock:
        if backend not in _loaded:
            from hpgen.runtime import load
            _loaded[backend] = load(_Path(__file__).parent, backend=backend)
        return _loaded[backend]


def step(g, p, h, **kw):
    """One step (g_k, p_k) -> (g_{k+1}, p_{k+1}) with the default backend (Integrator.step:
    z=, newton=)."""
    return integrator().step(g, p, h, **kw)


def simulate(**kw):
    """Integrator.simulate(g0=..., h=..., steps=..., xi0= or mu0=, every=1,
    newton=hpgen.runtime.NewtonOptions(...)) -> Trajectory."""
    return integrator().simulate(**kw)


def record(**kw):
    """Integrator.record(g0=..., h=..., steps=..., xi0= or mu0=, every=1, newton=...) ->
    Records: only the scene's record list (g, mu, energy, momentum, bottom), evaluated inside the step loop."""
    return integrator().record(**kw)

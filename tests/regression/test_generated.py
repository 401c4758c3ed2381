"""The golden modules committed in generated/ are current and run without the compile-time
stack (casadi, sympy, jinja2 unimportable); every shipped example generates deterministically
(the examples that are not golden are generated here, on demand)."""
from __future__ import annotations

import json
import shutil
import subprocess
import sys

import pytest

from hpgen.tools.generate_examples import GENERATED, example_sources, examples, golden_examples

EXAMPLES = examples()
GOLDEN = golden_examples()
SOURCES = ("__init__.py", "kernels.c", "kernels.py", "meta.json", "model.yaml")


@pytest.mark.parametrize("example", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_sources_are_deterministic_and_golden_ones_current(example):
    name, files = example_sources(example)
    _, again = example_sources(example)
    assert files == again, "generation is not deterministic"
    assert sorted(files) == sorted(SOURCES)
    if example not in GOLDEN:
        return
    for fname in SOURCES:
        committed = GENERATED / name / fname
        assert committed.exists(), f"{committed} missing: run `make generate`"
        assert committed.read_text() == files[fname], f"{committed} is stale: run `make generate`"


def test_generated_holds_the_golden_modules_only():
    """One module directory per golden example (its model file, as committed), nothing else."""
    modules = sorted(p for p in GENERATED.iterdir() if p.is_dir())
    texts = sorted((m / "model.yaml").read_text() for m in modules)
    assert texts == sorted(g.read_text() for g in GOLDEN), [m.name for m in modules]


BLOCKED_STEP = """
import sys
for mod in ("casadi", "sympy", "jinja2", "yaml", "scipy"):
    sys.modules[mod] = None          # any import of these now raises ImportError
sys.path.insert(0, sys.argv[1])
import importlib, numpy as np
mod = importlib.import_module(sys.argv[2])
integ = mod.integrator(backend=sys.argv[3])
n, d = integ.n, integ.d
g1, p1 = mod.step(np.eye(n), np.linspace(0.1, 0.3, d), 0.05) if sys.argv[3] == "c" else \
    integ.step(np.eye(n), np.linspace(0.1, 0.3, d), 0.05)
tr = integ.simulate(g0=np.eye(n), mu0=np.linspace(0.1, 0.3, d), h=0.05, steps=20)
assert np.isfinite(tr.mu).all() and tr.g.shape == (21, n, n)
rec = mod.record(g0=np.eye(n), mu0=np.linspace(0.1, 0.3, d), h=0.05, steps=20, every=5) \
    if sys.argv[3] == "c" else integ.record(g0=np.eye(n), mu0=np.linspace(0.1, 0.3, d),
                                            h=0.05, steps=20, every=5)
assert rec.names == integ.record_names and "energy" in rec.names
assert np.array_equal(rec["g"], tr.g[::5]) and np.array_equal(rec["mu"], tr.mu[::5])
assert all(np.isfinite(rec[name]).all() for name in rec.names)
assert not any(m in sys.modules and sys.modules[m] is not None
               for m in ("casadi", "sympy", "jinja2", "hpgen.derive", "hpgen.codegen", "hpgen.model"))
print("ok", integ.backend, float(np.abs(p1).sum()))
"""


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("module", sorted(p.name for p in GENERATED.iterdir() if p.is_dir()))
def test_generated_module_steps_without_compile_stack(tmp_path, module, backend):
    name = json.loads((GENERATED / module / "meta.json").read_text())["module"]
    shutil.copytree(GENERATED / name, tmp_path / name)   # builds the library in tmp, not in the repo
    out = subprocess.run([sys.executable, "-c", BLOCKED_STEP, str(tmp_path), name, backend],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith(f"ok {backend}")

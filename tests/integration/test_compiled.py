"""hpgen.build returns what the compile produced (hpgen.api.CompiledModule), and its
consumers (hpgen check, hpgen bench) reuse it: nothing is resolved, derived or compiled a
second time, and no cache path is rebuilt outside hpgen.api."""
from __future__ import annotations

import pytest

import hpgen
import hpgen.api as api
from conftest import EXAMPLES, FREE_BODY

OPTS = dict(tableau="midpoint", tau="cay", rkmk="exact")


@pytest.fixture
def derivations(monkeypatch):
    """The derive_module calls made (arguments), counted through hpgen.api."""
    calls, real = [], api.derive_module
    monkeypatch.setattr(api, "derive_module", lambda *a: calls.append(a) or real(*a))
    return calls


def test_build_returns_its_derivation_and_cache_status(tmp_path, model_file, derivations):
    path = model_file(FREE_BODY)
    cold = hpgen.build(path, cache_dir=tmp_path, **OPTS)
    assert not cold.cached and cold.built and len(derivations) == 1
    d = cold.derivation
    assert d is cold.derived
    assert (d.tableau.name, d.tau, d.rkmk) == tuple(cold.meta["options"][k]
                                                    for k in ("tableau", "tau", "rkmk"))
    assert (d.step.n, d.step.d, d.step.nz) == (cold.meta["n"], cold.meta["d"],
                                               cold.meta["nz"])
    warm = hpgen.build(path, cache_dir=tmp_path, **OPTS)
    assert warm.cached and not warm.built and warm.derived is None and len(derivations) == 1
    assert warm.module_dir == cold.module_dir and warm.meta == cold.meta
    # on a cache hit the step is derived when asked for, once
    assert warm.derivation.step.nz == d.step.nz and len(derivations) == 2
    assert warm.derivation is warm.derivation and len(derivations) == 2
    integ = warm.load()
    assert integ.meta == warm.meta and integ.backend == "c"
    assert warm.load("python").backend == "python"


def test_build_with_out_points_at_the_copy(tmp_path, model_file):
    cm = hpgen.build(model_file(FREE_BODY), cache_dir=tmp_path / "cache", out=tmp_path / "o",
                     **OPTS)
    assert cm.module_dir == tmp_path / "o" / cm.meta["module"]
    assert (cm.module_dir / "meta.json").exists()


def test_check_derives_once(tmp_path, derivations):
    from hpgen.analysis.check import run_check
    r = run_check(EXAMPLES / "free_rigid_body.yaml", steps=20, cache_dir=tmp_path, n_states=1,
                  **OPTS)
    assert r["integrator"]["tableau"] == "midpoint" and r["checks"]["symplectic"]
    assert len(derivations) == 1          # the compile's derivation is the check's step
    run_check(EXAMPLES / "free_rigid_body.yaml", steps=20, cache_dir=tmp_path, n_states=1,
              **OPTS)
    assert len(derivations) == 2          # a cache hit: derived once, for the Jacobians

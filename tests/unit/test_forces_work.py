"""The ``power`` and ``work`` records of a forced model (hpgen.runtime.work): the quadrature's
exactness, energy - work conserved to the scheme's order, chunks / every / batches / backends
bitwise, and the refusal of work on a model without forces."""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.errors import ModelError
from hpgen.runtime import NewtonOptions
from hpgen.runtime.work import WorkSum

from test_derive_forces import HEAVY_TOP

FULL = NewtonOptions(simplified=False)
SCENE = """\
scene:
  h: 0.05
  steps: 60
  initial: {g: identity, xi: [0.2, 1.0, 3.0]}
  record: [energy, work, power]
"""
XI0 = [0.2, 1.0, 3.0]


@pytest.fixture(scope="module")
def tops(tmp_path_factory):
    root = tmp_path_factory.mktemp("work")
    path = root / "top.yaml"
    path.write_text(HEAVY_TOP + SCENE)
    return {(tab, be): hpgen.compile(path, tableau=tab, tau="cay", rkmk="exact", backend=be,
                                     cache_dir=root / "cache")
            for tab in ("gauss2", "gauss3") for be in ("c", "python")}


def test_quadrature_exact_for_quintics_and_chunk_free():
    """W of t^j (j <= 4 everywhere, j = 5 from node 4) to round-off; fed in pieces, bitwise
    the whole."""
    h, t = 0.01, np.arange(201) * 0.01
    for j in range(6):
        W = WorkSum(h).add(t ** j)
        exact = t ** (j + 1) / (j + 1)
        assert np.abs(W - exact)[4 if j == 5 else 0:].max() <= 50 * np.finfo(float).eps
    P = np.random.default_rng(1).standard_normal(40)
    acc = WorkSum(0.1)
    parts = np.concatenate([acc.add(P[:5]), acc.add(P[5:8]), acc.add(P[8:9]), acc.add(P[9:])])
    assert np.array_equal(parts, WorkSum(0.1).add(P))


@pytest.mark.parametrize("tableau,order", [("gauss2", 4), ("gauss3", 6)])
def test_energy_minus_work_is_conserved_to_the_order(tops, tableau, order):
    """max_k |(E - W)_k - E_0| over t in [0, 4] falls as h^order (halving h: a ratio within
    25% of 2^order, measured 16.9 / 16.6 and 63.4 / 63.3); the work is not small (the
    damping and the driving change E by ~4)."""
    top = tops[tableau, "c"]
    errs = []
    for h in (0.1, 0.05, 0.025):
        r = top.record(np.eye(3), h, int(round(4 / h)), xi0=XI0, newton=FULL)
        bal = r["energy"] - r["work"]
        errs.append(np.abs(bal - bal[0]).max())
        assert abs(r["work"][-1]) > 1.0
    for a, b in zip(errs, errs[1:]):
        assert 0.75 * 2 ** order <= a / b <= 1.25 * 2 ** order


def test_work_every_chunks_batches_and_backends_bitwise(tops):
    """every and chunks keep the every-step run's values; record_batch and the Python backend
    equal record on the C backend bitwise; power is <f, xi> of the recorded state."""
    top = tops["gauss2", "c"]
    kw = dict(xi0=XI0, params={"Mg": 1.3}, t0=0.3)
    r1 = top.record(np.eye(3), 0.05, 80, **kw)
    r10 = top.record(np.eye(3), 0.05, 80, every=10, **kw)
    assert np.array_equal(r10["work"], r1["work"][::10])
    assert np.array_equal(r10["power"], r1["power"][::10])
    for chunk in (1, 3, 7):
        parts = list(top.stream_record(np.eye(3), 0.05, 80, every=2, chunk=chunk, **kw))
        assert np.array_equal(np.concatenate([p["work"] for p in parts]), r1["work"][::2])
    batch = top.record_batch(np.eye(3), 0.05, 80, xi0=[XI0, XI0], every=10,
                             params={"Mg": [1.3, 1.3]}, t0=0.3)
    for rec in batch:
        assert all(np.array_equal(rec[k], r10[k]) for k in r10.names)
    py = tops["gauss2", "python"].record(np.eye(3), 0.05, 80, every=10, **kw)
    assert all(np.array_equal(py[k], r10[k]) for k in r10.names)
    sim = top.simulate(np.eye(3), 0.05, 80, **kw)
    xi, t = sim.xi(), sim.t
    c, a = 0.1, 0.4
    f = np.stack([-c * xi[:, 0] + a * np.cos(2 * t), -c * xi[:, 1],
                  -c * xi[:, 2] + a * sim.g[:, 2, 0] * np.sin(t)], axis=1)
    assert np.abs(np.einsum("ki,ki->k", f, xi) - r1["power"]).max() <= 1e-13


def test_work_needs_forces(tmp_path):
    path = tmp_path / "free.yaml"
    path.write_text(HEAVY_TOP.split("forces:")[0].replace("runtime_parameters: [Mg]\n", "")
                    + SCENE)
    with pytest.raises(ModelError, match=r"scene.record\[1\].*'work' is the work of the forces"):
        hpgen.compile(path, cache_dir=tmp_path / "cache")


def test_work_is_not_a_label_of_a_forced_model(tmp_path):
    """Without forces `work` may label an expression (files before issue 16 stay valid);
    with forces it is the built-in record."""
    path = tmp_path / "labelled.yaml"
    path.write_text(HEAVY_TOP + SCENE.replace("[energy, work, power]", '[{work: "xi[0]"}]'))
    with pytest.raises(ModelError, match="the label 'work' is a built-in record name"):
        hpgen.compile(path, cache_dir=tmp_path / "cache")


def test_hpgen_run_prints_the_energy_work_balance(tops, tmp_path):
    """hpgen run on a forced scene that records energy and work: the balance line (its value
    the records' max |(E - W) - E_0|), no 'energy error' line."""
    import re
    import subprocess
    import sys
    path = tmp_path / "top.yaml"
    path.write_text(HEAVY_TOP + SCENE)
    run = subprocess.run([sys.executable, "-m", "hpgen", "run", str(path), "--out",
                          str(tmp_path / "o.npz"), "--cache-dir", str(tmp_path / "cache"),
                          "--tableau", "gauss2", "--tau", "cay", "--rkmk", "exact",
                          "--no-plot"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    assert "energy error" not in run.stdout
    m = re.search(r"energy-work balance max \|\(E - W\) - E0\| = (\S+)", run.stdout)
    out = np.load(tmp_path / "o.npz")
    bal = out["energy"] - out["work"]
    assert m and float(m.group(1)) == pytest.approx(np.abs(bal - bal[0]).max(), rel=1e-3)

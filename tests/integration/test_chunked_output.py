"""Chunked runs to disk (hpgen.runtime.chunked_output, ``hpgen run --chunk``): the file equals the
one the whole run saves from memory, with partial runs saved before the failure."""
from __future__ import annotations

import re

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen import compile as hpgen_compile
from hpgen.errors import ConvergenceError
from hpgen.model import load_model
from hpgen.runtime.chunked_output import record_to_npz

NAMES = ("g", "mu", "xi", "energy", "momentum", "defect")


@pytest.fixture(scope="module")
def top(tmp_path_factory):
    """The heavy top (Stormer-Verlet, Cayley, q = 0) compiled for a scene that records all
    six built-in names."""
    cache = tmp_path_factory.mktemp("cache")
    text = re.sub(r"(?m)^  record: .*$", f"  record: [{', '.join(NAMES)}]",
                  (EXAMPLES / "heavy_top.yaml").read_text())
    path = tmp_path_factory.mktemp("model") / "heavy_top_all.yaml"
    path.write_text(text)
    integ = hpgen_compile(path, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                          cache_dir=cache)
    return integ, load_model(path).scene


@pytest.mark.parametrize("steps, every, chunk", [(200, 10, 7), (200, 10, 10), (203, 10, 50),
                                                 (0, 3, 5), (50, 1, 1000)])
def test_chunked_file_equals_the_in_memory_one(top, tmp_path, steps, every, chunk):
    integ, sc = top
    assert integ.record_names == NAMES
    kw = dict(g0=sc.g0, h=sc.h, steps=steps, xi0=sc.xi0, every=every)
    path, summary = record_to_npz(integ, tmp_path / "chunked", chunk=chunk, **kw)
    rec = integ.record(**kw)
    whole = rec.save(tmp_path / "whole")
    a, b = np.load(path), np.load(whole)
    assert path.name == "chunked.npz" and whole.name == "whole.npz"
    assert sorted(a.files) == sorted(b.files) == sorted(
        ["t", *NAMES, "h", "every", "partial", "newton_iterations", "guarded", "error", "module",
         "hash", "group", "forced"])
    for key in b.files:
        assert np.array_equal(a[key], b[key]), key     # bitwise: the same states and kernels
    # the states are simulate's, bitwise; the observables agree with Trajectory's (kernel
    # observe, the same formulas written once more) to round-off
    traj = integ.simulate(**kw)
    assert np.array_equal(a["g"], traj.g) and np.array_equal(a["mu"], traj.mu)
    for key in ("xi", "energy", "momentum", "defect"):
        ref = traj.observables([key])[key]
        assert np.allclose(a[key], ref, rtol=1e-14, atol=1e-15), key
    assert summary["samples"] == steps // every + 1 == len(a["t"])
    e = a["energy"]
    assert summary["energy_max_change"] == np.abs(e - e[0]).max()
    assert not list(tmp_path.glob(".chunked*")), "temporary files left behind"


SPRING = """
name: spring
group: R2
parameters: {k: 10000.0}
lagrangian: 0.5*(xi[0]**2 + xi[1]**2) - 0.5*k*(x[0]**2 + x[1]**2)
"""


def test_failed_run_saves_the_records_before_the_failure(compile_model, tmp_path):
    # Stormer-Verlet past its stability limit (omega h = 10): the state grows like |lam|^k
    # and overflows after about 70 steps; the step then reports non-finite values
    integ = compile_model(SPRING, tableau="stormer-verlet", tau="cay", rkmk="truncated")
    g0 = np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    kw = dict(g0=g0, h=0.1, steps=1000, xi0=[0.0, 50.0], every=2)
    with pytest.raises(ConvergenceError) as info:
        integ.simulate(**kw)
    failed_at = info.value.step
    assert failed_at > 20
    with pytest.raises(ConvergenceError) as info2:
        record_to_npz(integ, tmp_path / "part.npz", chunk=7, **kw)
    assert info2.value.step == failed_at
    path, n = info2.value.saved
    data = np.load(path)
    assert bool(data["partial"]) and data["error"].item() != ""
    assert n == len(data["t"]) == failed_at // 2 + 1
    assert np.array_equal(data["g"], info.value.partial.g)
    assert np.array_equal(data["mu"], info.value.partial.mu)

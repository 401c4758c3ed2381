"""record_to_npz interrupted after some chunks and resumed (hpgen.runtime.chunked_output), in
process, for the backends' run snapshots: C (the hpgen_run bytes), Python with the printed
linear solver (J^{-1} kept as a tuple) and with the numpy solver (nz > 12: an array). The
resumed file's arrays equal the uninterrupted run's bitwise, Newton counts included; so do
those of a run interrupted as its first chunk is committed (a signal deferred by the commit's
write, raised as it returns) or just after (an interrupt or an exception in the next chunk)."""
from __future__ import annotations

import signal

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen import compile as hpgen_compile
from hpgen.cli_interrupts import sigterm_raises
from hpgen.model import load_model
from hpgen.runtime import partial_run
from hpgen.runtime.chunked_output import load_partial, partial_dir, record_to_npz

CASES = [("heavy_top", "gauss2", "exp", "c", 240), ("heavy_top", "gauss2", "exp", "python", 120),
         ("underwater_vehicle", "gauss2", "cay", "python", 40)]
CHUNK = 10


@pytest.mark.parametrize("example, tableau, tau, backend, steps", CASES)
def test_interrupted_then_resumed_equals_uninterrupted(cache_dir, tmp_path, example, tableau,
                                                       tau, backend, steps):
    path = EXAMPLES / f"{example}.yaml"
    integ = hpgen_compile(path, tableau=tableau, tau=tau, rkmk="exact", backend=backend,
                          cache_dir=cache_dir)
    sc = load_model(path).scene
    kw = dict(g0=sc.g0, h=sc.h, steps=steps, xi0=sc.xi0, mu0=sc.mu0, every=sc.every // 2 or 1,
              chunk=CHUNK)
    ref_path, ref_summary = record_to_npz(integ, tmp_path / "ref", **kw)

    advance, calls = integ.engine.backend.advance_record, []

    def interrupted(*a, **k):        # the 4th chunk is interrupted: 3 are committed
        calls.append(1)
        if len(calls) == 4:
            raise KeyboardInterrupt
        return advance(*a, **k)
    integ.engine.backend.advance_record = interrupted
    try:
        with pytest.raises(KeyboardInterrupt) as info:
            record_to_npz(integ, tmp_path / "run", **kw)
    finally:
        del integ.engine.backend.advance_record
    saved, samples, k, parts = info.value.saved
    assert k == 3 * CHUNK and parts == partial_dir(tmp_path / "run.npz")
    with np.load(saved) as f, np.load(ref_path) as r:
        assert bool(f["partial"]) and len(f["t"]) == samples
        for key in ("t", *integ.record_names):
            assert np.array_equal(f[key], r[key][:samples]), key
        assert np.array_equal(load_partial(saved)["t"], r["t"][:samples])

    summary = _resumed_equals(integ, tmp_path / "run", kw, ref_path, ref_summary)
    assert summary["resumed_at"] == 3 * CHUNK and summary["steps"] == steps
    assert not parts.exists()


def _resumed_equals(integ, out, kw, ref_path, ref_summary) -> dict:
    """Resume the run of ``out``; check its file and summary against the uninterrupted
    run's, bitwise (Newton counts included); return the summary."""
    path, summary = record_to_npz(integ, out, resume=True, **kw)
    with np.load(path) as f, np.load(ref_path) as r:
        assert sorted(f.files) == sorted(r.files)
        for key in r.files:
            assert np.array_equal(f[key], r[key]), key
    for key in ("samples", "newton_iterations", "energy_max_change", "momentum_max_change"):
        assert np.array_equal(summary[key], ref_summary[key]), key
    return summary


def test_an_older_hpgen_leftover_is_removed_and_named(cache_dir, tmp_path):
    # hpgen <= 0.1 left a hidden folder of preallocated memory maps per killed run
    old = tmp_path / ".run.npz.t_x1y2"
    old.mkdir()
    np.lib.format.open_memmap(old / "g.npy", mode="w+", dtype=np.float64, shape=(1000, 3, 3))
    keep = tmp_path / ".other.npz.t_x1y2"        # another output's: not touched
    keep.mkdir()
    path = EXAMPLES / "free_rigid_body.yaml"
    integ = hpgen_compile(path, cache_dir=cache_dir)
    sc = load_model(path).scene
    out, summary = record_to_npz(integ, tmp_path / "run.npz", g0=sc.g0, h=sc.h, steps=20,
                                 xi0=sc.xi0, mu0=sc.mu0, chunk=7)
    assert summary["removed"] == [old] and not old.exists() and keep.is_dir()
    assert sorted(p.name for p in tmp_path.iterdir()) == [".other.npz.t_x1y2", "run.npz"]


def _signal_in_first_commit(sig):
    """A write_npz that sends ``sig`` to this process once chunk 0 is written: the signal
    comes while the commit defers it, and is raised as the commit returns."""
    write = partial_run.write_npz

    def hooked(path, arrays):
        write(path, arrays)
        if path.name == "chunk_000000.npz":
            signal.raise_signal(sig)
    return hooked


def _raise_in_second_chunk(exc, advance):
    calls = []

    def hooked(*a, **k):
        calls.append(1)
        if len(calls) == 2:
            raise exc
        return advance(*a, **k)
    return hooked


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("how", ["sigint-in-commit", "sigterm-in-commit",
                                 "interrupt-after", "exception-after"])
def test_interrupted_right_after_the_first_commit_keeps_it_and_resumes(
        cache_dir, tmp_path, monkeypatch, backend, how):
    path = EXAMPLES / "heavy_top.yaml"
    integ = hpgen_compile(path, tableau="gauss2", tau="exp", rkmk="exact", backend=backend,
                          cache_dir=cache_dir)
    sc = load_model(path).scene
    kw = dict(g0=sc.g0, h=sc.h, steps=4 * CHUNK, xi0=sc.xi0, mu0=sc.mu0, every=3, chunk=CHUNK)
    ref_path, ref_summary = record_to_npz(integ, tmp_path / "ref", **kw)
    engine = integ.engine.backend
    if how.endswith("in-commit"):
        sig = signal.SIGINT if how == "sigint-in-commit" else signal.SIGTERM
        monkeypatch.setattr(partial_run, "write_npz", _signal_in_first_commit(sig))
        expected = KeyboardInterrupt
    else:
        expected = KeyboardInterrupt if how == "interrupt-after" else RuntimeError
        monkeypatch.setattr(engine, "advance_record",
                            _raise_in_second_chunk(expected(), engine.advance_record))
    with sigterm_raises(), pytest.raises(expected) as info:
        record_to_npz(integ, tmp_path / "run", **kw)
    monkeypatch.undo()
    parts = partial_dir(tmp_path / "run.npz")
    assert [p.name for p in sorted(parts.glob("chunk_*.npz"))] == ["chunk_000000.npz"]
    if expected is KeyboardInterrupt:
        saved, samples, k, kept = info.value.saved
        assert (k, kept, samples) == (CHUNK, parts, len(load_partial(saved)["t"]))
        with np.load(saved) as f:
            assert info.value.counts["newton_iterations"] == int(f["newton_iterations"]) > 0
        assert getattr(info.value, "signum", signal.SIGINT) == (
            signal.SIGTERM if how == "sigterm-in-commit" else signal.SIGINT)
    summary = _resumed_equals(integ, tmp_path / "run", kw, ref_path, ref_summary)
    assert summary["resumed_at"] == CHUNK and not parts.exists()

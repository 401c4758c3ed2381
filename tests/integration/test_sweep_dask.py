"""hpgen.sweep on Dask: a LocalCluster of 2 worker processes on loopback (dashboard off).

The Dask path runs the same chunk function with the same C code (each worker builds the
shipped kernels.c with the same compiler and flags), so it must equal the local path bitwise;
and a worker killed by its pid in the middle of a chunk must cost nothing but time: the
scheduler reruns the chunk and the result is complete and bitwise equal.
"""
from __future__ import annotations

import os
import signal
import threading
import time

import numpy as np
import pytest

import hpgen
from conftest import EXAMPLES
from hpgen.ensemble import remote

distributed = pytest.importorskip("distributed")

W0 = np.array([0.2, 1.0, 3.0]) + 0.05 * np.arange(24).reshape(8, 3)


@pytest.fixture(scope="module")
def body(compile_model):
    return compile_model(EXAMPLES / "free_rigid_body.yaml")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster, \
            distributed.Client(cluster) as c:
        yield c


def _same(a, b):
    assert a.names == b.names
    for name in a.names:
        assert np.array_equal(a[name], b[name], equal_nan=True), name
    for name in ("failed", "error", "samples", "steps_done", "newton_iterations", "h"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


@pytest.mark.parametrize("record", [None, ["energy", "momentum"]])
def test_dask_equals_local_bitwise(body, client, record):
    h = np.full(len(W0), 0.1)
    h[5] = 1.5                                      # member 5 fails (Cayley map's domain)
    kw = dict(xi0=W0, h=h, steps=50, every=5, record=record, progress=False)
    local = hpgen.sweep(body, **kw)
    remote_ = hpgen.sweep(body, client=client, chunk_size=3, **kw)
    _same(remote_, local)
    assert remote_.failed.tolist() == [i == 5 for i in range(len(W0))]
    # each worker that ran a chunk loaded the module once, by its content hash
    digest = remote.payload_of(body).digest
    loaded = client.run(lambda: list(remote._LOADED))
    assert any(digest in keys for keys in loaded.values())


def test_worker_killed_mid_chunk_is_retried(body, client):
    """6 chunks of about 1 s each; once a worker is executing one, SIGKILL it. Bounded: the
    whole test takes 15-25 s on 2 shared cores (the sweep is waited on for at most 50 s)."""
    kw = dict(xi0=W0[:6], h=0.01, steps=3 * 10**6, every=10**5, record=["energy", "momentum"],
              progress=False)
    local = hpgen.sweep(body, **kw)
    out, failure = {}, []

    def run():
        try:
            out["res"] = hpgen.sweep(body, client=client, chunk_size=1, **kw)
        except BaseException as e:          # noqa: BLE001 (reported by the assert below)
            failure.append(e)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    victim = None
    deadline = time.monotonic() + 30
    while victim is None and time.monotonic() < deadline:
        busy = client.run(lambda dask_worker: (os.getpid(), [
            str(ts.key) for ts in dask_worker.state.executing if "run_task" in str(ts.key)]))
        victim = next((pid for pid, keys in busy.values() if keys), None)
        time.sleep(0.05)
    assert victim is not None, "no worker ever executed a chunk"
    time.sleep(0.2)                         # well inside the chunk (about 1 s)
    os.kill(victim, signal.SIGKILL)
    thread.join(timeout=50)
    assert not thread.is_alive() and not failure, failure
    with pytest.raises(ProcessLookupError):
        os.kill(victim, 0)
    _same(out["res"], local)
    assert not out["res"].failed.any()


def test_bad_member_on_a_worker_is_a_model_error(body, client):
    from hpgen.errors import ModelError
    g0 = np.broadcast_to(np.eye(3), (4, 3, 3)).copy()
    g0[2] *= 2.0                                        # member 2 is off the group
    with pytest.raises(ModelError, match="member 2: initial g: g0 is not on the group"):
        hpgen.sweep(body, g0=g0, xi0=W0[:4], h=0.1, steps=5, client=client, chunk_size=2,
                    progress=False)

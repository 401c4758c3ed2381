"""``hpgen run --chunk`` killed mid-run (issue 17, fault 4) and interrupted by SIGTERM / SIGINT:
the completed chunks stay readable in <out>.partial/, a new run names them (one line, exit
2), ``--resume`` continues from the last completed chunk, and the final file's arrays are
bitwise those of an uninterrupted run. SIGTERM / SIGINT also save the completed samples to
<out> flagged partial=True, print one line saying where and how to resume, and exit 143 /
130.

The runs are the heavy top (Stormer-Verlet, Cayley, q = 0: about 1 us a step) for 2e6 steps
in chunks of 5000 (400 chunks, a few seconds); the signal is sent once three chunks are
committed (their files exist), long before the run can end."""
from __future__ import annotations

import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.runtime.chunked_output import load_partial, partial_dir

STEPS, CHUNK = 2_000_000, 5000
SCHEME = ("--tableau", "stormer-verlet", "--tau", "cay", "--rkmk", "truncated")


def _argv(out, cache, *extra):
    return [sys.executable, "-m", "hpgen", "run", str(EXAMPLES / "heavy_top.yaml"), "--out",
            str(out), "--cache-dir", str(cache), "--steps", str(STEPS), "--chunk", str(CHUNK),
            "--no-plot", *SCHEME, *extra]


def _run(*argv):
    return subprocess.run(list(argv), capture_output=True, text=True, timeout=600)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The uninterrupted run's file (its arrays), and the shared build cache."""
    tmp = tmp_path_factory.mktemp("reference")
    out = _run(*_argv(tmp / "ref.npz", tmp / "cache"))
    assert out.returncode == 0, out.stderr[-3000:]
    with np.load(tmp / "ref.npz") as f:
        return {k: f[k] for k in f.files}, tmp / "cache"


def _start_and_signal(argv, out, sig):
    """Start the run, wait until 3 chunks are committed, send ``sig``; return the process."""
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    parts, t0 = partial_dir(out), time.monotonic()
    while len(list(parts.glob("chunk_*.npz"))) < 3:
        assert proc.poll() is None, f"the run ended before 3 chunks: {proc.communicate()}"
        assert time.monotonic() - t0 < 300, "no chunk committed in 300 s"
        time.sleep(0.005)
    assert proc.poll() is None, "the run ended before it could be interrupted"
    proc.send_signal(sig)
    return proc


def _assert_prefix(arrays, ref, n):
    """arrays (t and the records) equal the first n samples of the reference, bitwise."""
    assert 3 <= n < len(ref["t"])
    for name in ("t", "g", "mu", "energy", "momentum", "height"):
        assert np.array_equal(arrays[name], ref[name][:n]), name


def _resume_and_compare(out, cache, ref, tmp_path):
    again = _run(*_argv(out, cache, "--resume"))
    assert again.returncode == 0, again.stderr[-3000:]
    assert "resumed at step" in again.stdout
    with np.load(out) as f:
        assert sorted(f.files) == sorted(ref)
        for key in ref:
            assert np.array_equal(f[key], ref[key]), key      # bitwise, metadata included
    assert not partial_dir(out).exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.npz"]


def test_kill_9_keeps_completed_chunks_and_resume_equals_the_uninterrupted_run(
        reference, tmp_path):
    ref, cache = reference
    out = tmp_path / "run.npz"
    proc = _start_and_signal(_argv(out, cache), out, signal.SIGKILL)
    proc.communicate(timeout=60)
    assert proc.returncode == -signal.SIGKILL
    assert not out.exists()
    # the completed chunks are readable: each chunk file, and all of them joined
    parts = partial_dir(out)
    assert (parts / "manifest.json").is_file()
    part = load_partial(out)
    n = len(part["t"])
    _assert_prefix(part, ref, n)
    assert part["steps_done"] % CHUNK == 0 and part["steps_done"] // 10 + 1 == n
    with np.load(parts / "chunk_000000.npz") as f:
        _assert_prefix(f, ref, len(f["t"]))
    # a new run without --resume names what is left and how to continue, and changes nothing
    new = _run(*_argv(out, cache))
    assert new.returncode == 2, new.stderr[-3000:]
    line, = new.stderr.strip().splitlines()
    assert line.startswith(f"hpgen: error: {parts}: holds ") and "interrupted run" in line
    assert "--resume" in line and f"{part['steps_done']} of {STEPS} steps" in line
    # resuming with another step size is refused (the run would not be the same)
    other = _run(*_argv(out, cache, "--resume", "--h", "0.02"))
    assert other.returncode == 2 and "cannot resume" in other.stderr and " h " in other.stderr
    assert len(load_partial(out)["t"]) == n
    _resume_and_compare(out, cache, ref, tmp_path)


@pytest.mark.parametrize("sig, status", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_signal_saves_completed_chunks_partial_and_resumes(reference, tmp_path, sig, status):
    ref, cache = reference
    out = tmp_path / "run.npz"
    proc = _start_and_signal(_argv(out, cache), out, sig)
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == status, err[-3000:]
    line, = err.strip().splitlines()
    name = signal.Signals(sig).name
    assert line.startswith(f"hpgen: interrupted by {name} after "), line
    assert f"saved to {out} with partial=True" in line and "--resume" in line
    with np.load(out) as f:
        assert bool(f["partial"]) and "interrupted" in str(f["error"])
        n = len(f["t"])
        _assert_prefix(f, ref, n)
        assert f"the {n} samples" in line
    _resume_and_compare(out, cache, ref, tmp_path)

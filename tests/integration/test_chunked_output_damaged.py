"""A chunked run's folder of completed chunks with one damaged chunk file: ``--resume``
verifies every chunk (zip directory, local headers, CRC-32 of each member) and continues
from the last intact chunk before the damage, so the damaged chunk and those after it are
run again; the final file equals the uninterrupted run's bitwise."""
from __future__ import annotations

import zipfile

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen import compile as hpgen_compile
from hpgen.model import load_model
from hpgen.runtime.checked_npz import is_intact
from hpgen.runtime.chunked_output import partial_dir, record_to_npz

CHUNK, STEPS = 10, 80


@pytest.fixture(scope="module")
def heavy_top(cache_dir):
    path = EXAMPLES / "heavy_top.yaml"
    sc = load_model(path).scene
    integ = hpgen_compile(path, cache_dir=cache_dir)
    return integ, dict(g0=sc.g0, h=sc.h, steps=STEPS, xi0=sc.xi0, every=2, chunk=CHUNK)


def _interrupt_after(integ, kw, out, chunks):
    advance, calls = integ.engine.backend.advance_record, []

    def interrupted(*a, **k):
        calls.append(1)
        if len(calls) == chunks + 1:
            raise KeyboardInterrupt
        return advance(*a, **k)
    integ.engine.backend.advance_record = interrupted
    try:
        with pytest.raises(KeyboardInterrupt):
            record_to_npz(integ, out, **kw)
    finally:
        del integ.engine.backend.advance_record


@pytest.mark.parametrize("where,which", [(0.02, 1), (0.5, 1), (0.97, 1), ("truncated", 1),
                                         (0.5, 0), (0.5, 3)])
def test_resume_redoes_a_damaged_chunk(heavy_top, tmp_path, where, which):
    integ, kw = heavy_top
    ref, _ = record_to_npz(integ, tmp_path / "ref.npz", **kw)
    out = tmp_path / "run.npz"
    _interrupt_after(integ, kw, out, 4)
    bad = partial_dir(out) / f"chunk_{which:06d}.npz"
    data = bytearray(bad.read_bytes())
    if where == "truncated":
        del data[len(data) // 2:]
    else:
        data[int(where * len(data))] ^= 0x04                 # one flipped bit
    bad.write_bytes(bytes(data))
    others = [partial_dir(out) / f"chunk_{i:06d}.npz" for i in range(4) if i != which]
    assert not is_intact(bad) and all(is_intact(p) for p in others)
    path, summary = record_to_npz(integ, out, resume=True, **kw)
    assert summary["resumed_at"] == CHUNK * which            # from the chunk before it
    with np.load(path) as f, np.load(ref) as r:
        assert sorted(f.files) == sorted(r.files)
        for key in r.files:
            assert np.array_equal(f[key], r[key]), key
    assert not partial_dir(out).exists()


def test_cli_resume_after_a_flipped_byte(heavy_top, tmp_path, cache_dir, capsys):
    from hpgen import cli
    integ, kw = heavy_top
    out = tmp_path / "run.npz"
    argv = ["run", str(EXAMPLES / "heavy_top.yaml"), "--out", str(out), "--cache-dir",
            str(cache_dir), "--steps", str(STEPS), "--chunk", str(CHUNK), "--no-plot",
            "--no-progress"]
    assert cli.main(argv) == 0
    ref = {k: v for k, v in np.load(out).items()}
    out.unlink()
    sc = load_model(EXAMPLES / "heavy_top.yaml").scene
    _interrupt_after(integ, {**kw, "every": sc.every}, out, 3)
    bad = partial_dir(out) / "chunk_000001.npz"
    with zipfile.ZipFile(bad) as zf:            # the last byte of g's data: a wrong number
        info = zf.getinfo("g.npy")
        end = info.header_offset + 30 + len(info.filename) + len(info.extra) \
            + info.compress_size
    data = bytearray(bad.read_bytes())
    data[end - 1] ^= 0x01
    bad.write_bytes(bytes(data))
    capsys.readouterr()
    assert cli.main([*argv, "--resume"]) == 0, capsys.readouterr().err
    assert f"resumed at step {CHUNK}" in capsys.readouterr().out
    with np.load(out) as f:
        for key in ref:
            assert np.array_equal(f[key], ref[key]), key

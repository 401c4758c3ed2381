"""A damaged build never runs (issue 17, fault 3 and "The cache").

Every run that may meet a damaged library happens in a subprocess, so that a SIGILL or
SIGBUS would show as a negative exit status instead of killing the test session; results
must equal the clean build's bit for bit.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hpgen
from hpgen.errors import ModelError

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "examples" / "free_rigid_body.yaml"
ENV = dict(os.environ, PYTHONPATH=str(ROOT))

RUN = """
import sys
import numpy as np
import hpgen
integ = hpgen.compile(sys.argv[1], cache_dir=sys.argv[2])
tr = integ.simulate(np.eye(3), 0.1, 200, mu0=[0.4535961214255773, 0.0, 0.8912073600614354])
np.save(sys.argv[3], np.concatenate([np.ravel(tr.g), np.ravel(tr.mu)]))
"""


def _run(cache_dir, out):
    proc = subprocess.run([sys.executable, "-c", RUN, str(MODEL), str(cache_dir), str(out)],
                          capture_output=True, text=True, timeout=300, env=ENV)
    assert proc.returncode == 0, (proc.returncode, proc.stderr)
    return np.load(out), proc.stderr


def _flip_middle(p: Path):
    data = bytearray(p.read_bytes())
    mid = len(data) // 2
    data[mid:mid + 64] = bytes(b ^ 0xFF for b in data[mid:mid + 64])
    with open(p, "r+b") as fh:              # in place, as a disk fault would
        fh.write(data)


def _truncate(p: Path):
    os.truncate(p, 1000)


def _flip_bit(p: Path):
    with open(p, "r+b") as fh:
        fh.seek(0x10000)
        byte = fh.read(1)
        assert byte, "library smaller than 0x10000 bytes"
        fh.seek(0x10000)
        fh.write(bytes([byte[0] ^ 0x01]))


@pytest.fixture(scope="module")
def clean(tmp_path_factory):
    """(cache dir, reference result of the clean build, the clean library's bytes)."""
    cache_dir = tmp_path_factory.mktemp("cache")
    ref, _ = _run(cache_dir, cache_dir.parent / "ref.npy")
    (lib,) = [p for p in cache_dir.glob("*/_kernels_*.so") if p.parent.name != "lib"]
    return cache_dir, ref, lib.read_bytes()


def _libraries(cache_dir):
    return sorted(cache_dir.rglob("_kernels_*.so"))


@pytest.mark.parametrize("damage", [_flip_middle, _truncate, _flip_bit])
@pytest.mark.parametrize("where", ["entry", "all"])
def test_damaged_library_is_rebuilt_not_loaded(clean, tmp_path, damage, where):
    cache_dir, ref, good = clean
    libs = _libraries(cache_dir)
    assert len(libs) == 2                   # the entry's link and the shared store's file
    for lib in libs if where == "all" else [p for p in libs if p.parent.name != "lib"]:
        if lib.stat().st_nlink > 1:         # a hard link: damage a copy of its own
            data = lib.read_bytes()
            lib.unlink()
            lib.write_bytes(data)
        damage(lib)
    got, err = _run(cache_dir, tmp_path / "got.npy")
    np.testing.assert_array_equal(got, ref)
    assert all(p.read_bytes() == good for p in _libraries(cache_dir))
    if where == "all":
        assert "does not match its build record" in err and "rebuilding" in err


def test_compile_out_never_copies_a_damaged_library(clean, tmp_path):
    cache_dir, ref, good = clean
    for lib in _libraries(cache_dir):
        _truncate(lib)
    proc = subprocess.run([sys.executable, "-m", "hpgen", "compile", str(MODEL), "--cache-dir",
                           str(cache_dir), "-o", str(tmp_path / "out")],
                          capture_output=True, text=True, timeout=300, env=ENV)
    assert proc.returncode == 0, proc.stderr
    (module,) = (tmp_path / "out").iterdir()
    (lib,) = module.glob("_kernels_*.so")
    assert lib.read_bytes() == good


@pytest.fixture
def out_module(tmp_path):
    """A module written by ``hpgen.compile(..., out=...)`` (C library built)."""
    integ = hpgen.compile(MODEL, cache_dir=tmp_path / "cache", out=tmp_path / "out")
    (module,) = (tmp_path / "out").iterdir()
    assert (module / "MANIFEST.json").is_file() and integ.meta["module"] == module.name
    return module


@pytest.mark.parametrize("keep_library", [True, False])
def test_hand_edited_kernels_c_is_refused(out_module, keep_library):
    source = out_module / "kernels.c"
    text = source.read_text()
    source.write_text(text.replace("#define HPGEN_W ", "#define HPGEN_W 1 + ", 1))
    assert source.read_text() != text
    if not keep_library:
        for p in out_module.glob("_kernels_*"):
            p.unlink()
    with pytest.raises(ModelError, match="kernels.c differs from the digests .*regenerate"):
        hpgen.load(out_module, backend="c")
    assert bool(list(out_module.glob("_kernels_*.so"))) == keep_library   # nothing built
    proc = subprocess.run([sys.executable, "-c", "import sys, hpgen; hpgen.load(sys.argv[1])",
                           str(out_module)], capture_output=True, text=True, env=ENV,
                          timeout=120)
    assert proc.returncode == 1 and "kernels.c differs" in proc.stderr


def test_hand_edited_kernels_py_is_refused(out_module):
    source = out_module / "kernels.py"
    source.write_text(source.read_text() + "\n# edited\n")
    with pytest.raises(ModelError, match="kernels.py differs"):
        hpgen.load(out_module, backend="python")


def test_intact_out_module_loads_with_both_backends(out_module):
    g = [hpgen.load(out_module, backend=b).step(np.eye(3), [0.1, 0.2, 0.3], 0.1)[0]
         for b in ("c", "python")]
    np.testing.assert_array_equal(g[0], g[1])


def test_unwritable_cache_builds_in_a_temporary_directory(tmp_path):
    """A cache directory that cannot be written (here its parent is a regular file, which
    fails for root too; a read-only directory fails the same way for other users): one
    line on stderr, the module is built elsewhere, the run succeeds."""
    blocker = tmp_path / "file"
    blocker.write_text("not a directory\n")
    proc = subprocess.run([sys.executable, "-m", "hpgen", "compile", str(MODEL), "--cache-dir",
                           str(blocker / "cache"), "-o", str(tmp_path / "out")],
                          capture_output=True, text=True, timeout=300, env=ENV)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("hpgen: warning: the cache directory"), lines
    assert "Traceback" not in proc.stderr
    (module,) = (tmp_path / "out").iterdir()
    integ = hpgen.load(module, backend="c")
    assert integ.step(np.eye(3), [0.1, 0.2, 0.3], 0.1)[0].shape == (3, 3)

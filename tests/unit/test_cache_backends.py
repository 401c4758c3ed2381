"""A cache entry holds the sources of the backends compiled so far: a C compile writes no
kernels.py, the first Python compile (or CompiledModule.load(backend="python")) derives again
and adds it, atomically; an entry whose added source is damaged, missing or unlisted is
repaired, never loaded half-written; ``out=`` copies a module loadable with either backend."""
from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

import hpgen
from hpgen import cache
from hpgen.api import CompileOptions, content_hash, generate_files, read_model_text
from hpgen.errors import ModelError

from conftest import FREE_BODY

pytestmark = pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")

G0 = np.eye(3)
P0 = np.array([0.4, 0.1, 0.8])


def _listed(entry) -> set:
    return set(json.loads((entry / cache.MANIFEST).read_text())["files"])


def _expected(path) -> dict:
    """The module's files as one compile of both backends writes them."""
    text = read_model_text(path)
    opts = CompileOptions()
    return generate_files(str(path), text, opts, content_hash(text, opts))


def test_c_compile_writes_no_python_kernels_and_python_adds_them(tmp_path, model_file):
    path = model_file(FREE_BODY)
    c = hpgen.build(path, cache_dir=tmp_path, backend="c")
    entry = c.module_dir
    assert not (entry / "kernels.py").exists() and "kernels.py" not in _listed(entry)
    assert set(c.timings) == {"derive", "emit", "write", "cc"}
    with pytest.raises(ModelError, match="no kernels.py") as e:
        hpgen.load(entry, backend="python")
    assert "\n" not in str(e.value)
    py = hpgen.build(path, cache_dir=tmp_path, backend="python")
    assert py.module_dir == entry and not py.cached
    assert "kernels.py" in _listed(entry) and cache.is_valid(entry)
    want = _expected(path)
    for name in ("kernels.c", "kernels.py", "meta.json", "__init__.py"):
        assert (entry / name).read_text() == want[name], name
    # both backends step alike (the C library was not rebuilt by the Python compile)
    g_c, p_c = c.load().step(G0, P0, 0.1)
    g_p, p_p = py.load().step(G0, P0, 0.1)
    np.testing.assert_allclose(p_c, p_p, rtol=1e-13, atol=1e-15)
    again = hpgen.build(path, cache_dir=tmp_path, backend="python")
    assert again.cached and again.timings == {}


def test_load_of_the_other_backend_generates_its_source(tmp_path, model_file):
    path = model_file(FREE_BODY.replace("name: body", "name: body_other"))
    c = hpgen.build(path, cache_dir=tmp_path, backend="c")
    integ = c.load(backend="python")
    assert integ.backend == "python" and "kernels.py" in _listed(c.module_dir)
    # a Python-first entry gets kernels.c (and its library) on the first C compile
    other = tmp_path / "python-first"
    py = hpgen.build(path, cache_dir=other, backend="python")
    assert not (py.module_dir / "kernels.c").exists()
    with pytest.raises(hpgen.BuildError, match="kernels.c is missing"):
        hpgen.load(py.module_dir, backend="c")
    c2 = hpgen.build(path, cache_dir=other, backend="c")
    assert c2.module_dir == py.module_dir and c2.built
    assert (c2.module_dir / "kernels.c").read_text() == (c.module_dir / "kernels.c").read_text()


@pytest.mark.parametrize("damage", ["corrupt", "missing", "unlisted"])
def test_a_damaged_added_source_is_rebuilt(tmp_path, model_file, damage):
    path = model_file(FREE_BODY.replace("name: body", "name: body_damaged"))
    entry = hpgen.build(path, cache_dir=tmp_path, backend="c").module_dir
    hpgen.build(path, cache_dir=tmp_path, backend="python")
    kernels = entry / "kernels.py"
    good = kernels.read_text()
    if damage == "corrupt":
        kernels.write_text(good[: len(good) // 2])          # a write cut short
    elif damage == "missing":
        kernels.unlink()
    else:                                                   # written, never listed
        manifest = json.loads((entry / cache.MANIFEST).read_text())
        del manifest["files"]["kernels.py"]
        (entry / cache.MANIFEST).write_text(json.dumps(manifest))
        kernels.write_text("raise SystemExit('half-written')\n")
    integ = hpgen.compile(path, cache_dir=tmp_path, backend="python")
    assert kernels.read_text() == good and cache.is_valid(entry)
    assert integ.step(G0, P0, 0.1)[1].shape == (3,)
    assert not list(entry.glob(".*tmp*")), "temporary files left behind"


def test_out_copies_both_backends(tmp_path, model_file):
    path = model_file(FREE_BODY.replace("name: body", "name: body_out"))
    hpgen.build(path, cache_dir=tmp_path / "cache", backend="c")     # a C-only entry
    out = hpgen.build(path, cache_dir=tmp_path / "cache", backend="c", out=tmp_path / "out")
    files = {p.name for p in out.module_dir.iterdir()}
    assert {"kernels.c", "kernels.py", "meta.json", "__init__.py", "model.yaml"} <= files
    assert hpgen.load(out.module_dir, backend="python").backend == "python"


def test_add_files_replaces_each_file_then_the_manifest(tmp_path):
    entry = cache.write_tree(tmp_path / "e", {"a.txt": "a"})
    (entry / "b.txt").write_text("stale, unlisted")
    cache.add_files(entry, {"b.txt": "b"})
    assert _listed(entry) == {"a.txt", "b.txt"} and cache.has_files(entry, ("a.txt", "b.txt"))
    assert (entry / "b.txt").read_text() == "b"
    assert not cache.has_files(entry, ("c.txt",))
    (entry / "a.txt").write_text("changed")
    assert not cache.has_files(entry, ("b.txt",))            # the entry as a whole is checked

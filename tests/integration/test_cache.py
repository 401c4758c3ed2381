"""Build cache: a hit imports nothing of the compile-time stack, a corrupted entry is
rebuilt, and concurrent compiles of one input both succeed and share one entry."""
from __future__ import annotations

import re
import subprocess
import sys

import hpgen
from conftest import FREE_BODY

HEX64 = re.compile(r"[0-9a-f]{64}")


def _entries(cache_dir):
    return [p for p in cache_dir.iterdir() if p.is_dir() and HEX64.fullmatch(p.name)]


CACHED_COMPILE = """
import sys
for mod in ("casadi", "sympy", "jinja2"):
    sys.modules[mod] = None
import hpgen
integ = hpgen.compile(sys.argv[1], cache_dir=sys.argv[2], backend="c")
print(integ.meta["module"])
"""


def test_second_compile_is_served_from_cache_without_compile_stack(tmp_path, model_file):
    path = model_file(FREE_BODY)
    hpgen.compile(path, cache_dir=tmp_path, backend="c")
    out = subprocess.run([sys.executable, "-c", CACHED_COMPILE, str(path), str(tmp_path)],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "body_stormer_verlet_cay_exact"  # model defaults
    assert len(_entries(tmp_path)) == 1


def test_corrupted_entry_is_detected_and_rebuilt(tmp_path, model_file):
    path = model_file(FREE_BODY)
    hpgen.compile(path, cache_dir=tmp_path, backend="python")
    (entry,) = _entries(tmp_path)
    kernels = entry / "kernels.py"
    good = kernels.read_text()
    kernels.write_text(good.replace("def ", "def broken_", 1))
    integ = hpgen.compile(path, cache_dir=tmp_path, backend="python")
    assert kernels.read_text() == good
    g1, p1 = integ.step([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [0.4, 0.1, 0.8], 0.1)
    assert p1.shape == (3,)


def test_concurrent_compiles_share_one_entry(tmp_path, model_file):
    path = model_file(FREE_BODY.replace("name: body", "name: body_concurrent"))
    code = ("import sys, hpgen; i = hpgen.compile(sys.argv[1], cache_dir=sys.argv[2]); "
            "print(i.step([[1,0,0],[0,1,0],[0,0,1]], [0.4, 0.1, 0.8], 0.1)[1])")
    procs = [subprocess.Popen([sys.executable, "-c", code, str(path), str(tmp_path)],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for _ in range(2)]
    outs = [p.communicate(timeout=300) for p in procs]
    assert all(p.returncode == 0 for p in procs), [o[1] for o in outs]
    assert outs[0][0] == outs[1][0]
    assert len(_entries(tmp_path)) == 1
    assert not list(tmp_path.glob(".*tmp*")), "temporary directories left behind"

"""``hpgen plot`` and the figures of ``hpgen run`` (hpgen.plot): which PNGs a file gives,
that they are real non-empty PNGs, and that a bad file is one line on stderr with exit 2."""
from __future__ import annotations

import csv
import os
import stat
import subprocess
import sys

import numpy as np

from conftest import EXAMPLES, FREE_BODY, ROOT
from hpgen.bench.report import CSV_COLUMNS
from hpgen.cli import main
from hpgen.plot import _npz_arrays, envelope, plot_file

PNG = b"\x89PNG\r\n\x1a\n"
SECTION_BODY = FREE_BODY + """
scene:
  h: 0.1
  steps: 3000
  initial: {g: identity, mu: [0.4535961214255773, 0.0, 0.8912073600614354]}
  record: [mu]
  section: mu[1]
"""


def _png(path):
    data = path.read_bytes()
    assert data.startswith(PNG) and len(data) > 5000, path     # a drawn figure, not a stub
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask   # as open() would create it
    assert not list(path.parent.glob(".*.png"))                   # no temp file left
    return path


def test_run_writes_the_figures_of_what_it_records(tmp_path, cache_dir, capsys):
    out = tmp_path / "top.npz"
    assert main(["run", str(EXAMPLES / "heavy_top.yaml"), "--out", str(out), "--steps", "400",
                 "--cache-dir", str(cache_dir)]) == 0
    printed = capsys.readouterr().out
    # heavy_top records [g, mu, energy, momentum, height]: the group distance comes from g
    names = {f"top-{k}.png" for k in ("energy", "momentum", "group", "pose", "records")}
    assert {p.name for p in tmp_path.glob("*.png")} == names
    for name in names:
        _png(tmp_path / name)
        assert name in printed
    # hpgen plot on the file alone: no integrator, so no group distance (defect not recorded)
    for p in tmp_path.glob("*.png"):
        p.unlink()
    assert main(["plot", str(out), "--out-dir", str(tmp_path / "figs")]) == 0
    assert {p.name for p in (tmp_path / "figs").glob("*.png")} == names - {"top-group.png"}


def test_run_no_plot_writes_no_png(tmp_path, cache_dir):
    assert main(["run", str(EXAMPLES / "heavy_top.yaml"), "--out", str(tmp_path / "a.npz"),
                 "--steps", "20", "--no-plot", "--cache-dir", str(cache_dir)]) == 0
    assert not list(tmp_path.glob("*.png"))


def test_trajectory_file_and_group_distance_from_the_integrator(tmp_path, compile_model):
    integ = compile_model(FREE_BODY, backend="c")
    tr = integ.simulate(g0=np.eye(3), mu0=[0.45, 0.0, 0.89], h=0.1, steps=200)
    path = tr.save(tmp_path / "tr.npz")
    assert [p.name for p in plot_file(path)] == ["tr-pose.png", "tr-records.png"]  # t, g, mu
    files = plot_file(path, out_dir=tmp_path / "b", integrator=integ)
    assert [p.name for p in files] == ["tr-group.png", "tr-pose.png", "tr-records.png"]
    for f in files:
        _png(f)


def test_section_file_gives_the_crossings_figure(tmp_path, cache_dir, model_file):
    model = model_file(SECTION_BODY)
    out = tmp_path / "sec.npz"
    assert main(["run", str(model), "--out", str(out), "--cache-dir", str(cache_dir)]) == 0
    assert len(np.load(out)["t"]) > 10
    assert [p.name for p in tmp_path.glob("*.png")] == ["sec-sections.png"]
    _png(tmp_path / "sec-sections.png")


def test_bench_directory_gives_work_precision(tmp_path, capsys):
    rows = [("hpgen a", "hpgen a", "hpgen", "h", 0.1 / 2 ** k, 10.0 ** -k, "", "", 1e-4 * 2 ** k)
            for k in range(3)] + [("DOP853", "DOP853", "peer", "rtol", 1e-6, 1e-7, "", "", 1e-3),
                                  ("DOP853", "DOP853", "peer", "rtol", 1e-8, float("nan"), "",
                                   "", 2e-3)]
    with open(tmp_path / "work_precision.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_COLUMNS)
        for r in rows:
            w.writerow([*r, "", "", 3, 0.0, ""])
    assert main(["plot", str(tmp_path)]) == 0
    assert capsys.readouterr().out.strip() == str(tmp_path / "work_precision.png")
    _png(tmp_path / "work_precision.png")


def _bad_files(tmp_path):
    (tmp_path / "junk.npz").write_bytes(bytes(range(256)) * 8)
    np.savez(tmp_path / "no_t.npz", x=np.arange(3.0))
    np.savez(tmp_path / "empty.npz", t=np.zeros(0))
    np.savez(tmp_path / "text.npz", t=np.arange(3.0), s=np.array(["a", "b", "c"]))
    np.savez(tmp_path / "short.npz", t=np.arange(3.0), energy=np.arange(2.0))
    np.savez(tmp_path / "g_only.npz", t=np.arange(2.0), g=np.stack([np.eye(5)] * 2))
    (tmp_path / "bench").mkdir()
    (tmp_path / "bench" / "work_precision.csv").write_text("a,b\n1,2\n")
    return ["missing.npz", "junk.npz", "no_t.npz", "empty.npz", "text.npz", "short.npz",
            "g_only.npz", "bench", "."]


def test_bad_files_are_one_line_exit_2(tmp_path, capsys):
    for name in _bad_files(tmp_path):
        assert main(["plot", str(tmp_path / name)]) == 2, name
        err = capsys.readouterr().err
        assert err.startswith("hpgen: error: ") and err.count("\n") == 1, err
        assert str(tmp_path / name).rstrip("/.") in err
    assert not list(tmp_path.rglob("*.png"))


def test_bad_file_from_a_fresh_process_has_no_traceback(tmp_path):
    (tmp_path / "junk.npz").write_bytes(b"PK\x03\x04" + b"\0" * 100)
    out = subprocess.run([sys.executable, "-m", "hpgen", "plot", str(tmp_path / "junk.npz")],
                         capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert out.stderr.count("\n") == 1 and "junk.npz" in out.stderr


def test_matplotlib_is_not_imported_by_the_runtime_path_or_the_parser():
    code = ("import sys, hpgen.plot, hpgen.cli, hpgen.runtime; hpgen.cli._parser(); "
            "print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120, cwd=ROOT)
    assert out.stdout.strip() == "False", out.stderr


def test_envelope_keeps_the_peaks():
    t = np.arange(100_000) * 0.01
    y = np.zeros_like(t)
    y[12_345] = 7.0
    tt, yy = envelope(t, y, n=1000)
    assert len(tt) == 1000 and yy.max() == 7.0 and tt[0] == 0.0
    t2, y2 = envelope(t[:50], y[:50], n=1000)
    assert len(t2) == 50


def test_large_files_are_read_by_memory_map_and_blocks(tmp_path):
    """A run file is memory-mapped (np.savez stores members uncompressed) and the binned
    maxima are computed a block of rows at a time: the same figures as in memory."""
    rng = np.random.default_rng(3)
    K = 250_001
    t = np.arange(K) * 0.01
    m = rng.standard_normal((K, 3)).cumsum(axis=0) * 1e-9
    np.savez(tmp_path / "big.npz", t=t, momentum=m, h=np.float64(0.01), module=np.str_("x"))
    np.savez_compressed(tmp_path / "small.npz", t=t[:10], momentum=m[:10])
    data = _npz_arrays(tmp_path / "big.npz")
    assert isinstance(data["momentum"], np.memmap) and str(data["module"]) == "x"
    assert np.array_equal(data["momentum"], m) and float(data["h"]) == 0.01
    assert np.array_equal(_npz_arrays(tmp_path / "small.npz")["momentum"], m[:10])
    ref = m[0]
    tt, blocked = envelope(data["t"], data["momentum"], n=997, ref=ref, block=1000)
    edges = np.linspace(0, K, 998).astype(np.int64)
    direct = np.maximum.reduceat(np.abs(m - ref), edges[:-1], axis=0)
    assert np.array_equal(tt, t[edges[:-1]]) and np.array_equal(blocked, direct)
    assert [p.name for p in plot_file(tmp_path / "big.npz")] == ["big-momentum.png"]

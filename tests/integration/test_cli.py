"""The command line on the shipped examples: compile, run, list."""
from __future__ import annotations

import re
import subprocess
import sys

import numpy as np

from conftest import EXAMPLES


def hpgen(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "hpgen", *map(str, args)], capture_output=True,
                          text=True, timeout=600, cwd=cwd)


def test_list():
    """`hpgen list` shows every group family and every registered option value."""
    from hpgen import schemes
    from hpgen.groups import GROUP_NAMES
    out = hpgen("list")
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    listed = {ln.split()[0] for ln in lines if ln.startswith("  ")}
    registered = ({t.name for t in schemes.tableaus()} | {s.name for s in schemes.splittings()}
                  | {c.name for c in schemes.compositions()})
    for option in (schemes.TAU, schemes.RKMK, schemes.BACKEND):
        registered |= set(option.names)
    assert listed == registered
    for t in schemes.tableaus():
        assert f"order {t.order}" in next(ln for ln in lines if ln.split()[:1] == [t.name])
    assert all(g in lines[0] for g in GROUP_NAMES)


def test_compile_writes_module(tmp_path):
    out = hpgen("compile", EXAMPLES / "free_rigid_body.yaml", "--tableau", "midpoint", "--tau",
                "exp", "-o", tmp_path / "gen", "--cache-dir", tmp_path / "cache")
    assert out.returncode == 0, out.stderr
    module = tmp_path / "gen" / "free_rigid_body_midpoint_exp_truncated"
    assert {p.name for p in module.iterdir()} >= {"kernels.c", "kernels.py", "__init__.py",
                                                  "meta.json", "model.yaml"}


def test_run_scene_saves_requested_records(tmp_path):
    out = hpgen("run", EXAMPLES / "heavy_top.yaml", "--out", tmp_path / "top.npz", "--steps", "200",
                "--cache-dir", tmp_path / "cache")
    assert out.returncode == 0, out.stderr
    data = np.load(tmp_path / "top.npz")
    assert data["g"].shape == (21, 3, 3) and data["mu"].shape == (21, 3)
    assert data["energy"].shape == (21,) and data["momentum"].shape == (21, 3)
    assert not data["partial"]
    # vertical spatial momentum e3.(R p) is the heavy top's conserved component
    assert np.ptp(data["momentum"][:, 2]) < 1e-12 * np.abs(data["mu"]).max()
    assert "energy error" in out.stdout


def test_run_scene_with_record_expressions(tmp_path):
    # the row compiled into the loop: only what record: lists is saved, labels included
    text = re.sub(r"(?m)^  record: .*$", '  record: [energy, {spin: "xi[2]"}, {p0: "mu[0]"}]',
                  (EXAMPLES / "free_rigid_body.yaml").read_text())
    model = tmp_path / "body.yaml"
    model.write_text(text)
    out = hpgen("run", model, "--out", tmp_path / "body.npz", "--steps", "100",
                "--cache-dir", tmp_path / "cache")
    assert out.returncode == 0, out.stderr
    data = np.load(tmp_path / "body.npz")
    assert {"t", "energy", "spin", "p0"} <= set(data.files)
    assert not {"g", "mu", "xi", "momentum"} & set(data.files)
    assert data["spin"].shape == data["p0"].shape == (101,)
    import hpgen as api
    from hpgen.model import load_model
    sc = load_model(model).scene
    rec = api.compile(model, cache_dir=tmp_path / "cache").record(
        sc.g0, sc.h, 100, mu0=sc.mu0, every=sc.every)
    for name in ("t", "energy", "spin", "p0"):
        assert np.array_equal(data[name], rec.t if name == "t" else rec[name]), name
    assert data["p0"][0] == sc.mu0[0]


def test_bad_option_exits_2_with_one_line(tmp_path):
    out = hpgen("compile", EXAMPLES / "underwater_vehicle.yaml", "--tau", "skew", "-o",
                tmp_path / "gen", "--cache-dir", tmp_path / "cache")
    assert out.returncode == 2
    assert out.stderr.startswith("hpgen: error: ") and len(out.stderr.strip().splitlines()) == 1
    assert "skew" in out.stderr and "SE3" in out.stderr
    assert not (tmp_path / "gen").exists()

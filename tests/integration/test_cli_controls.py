"""Control inputs outside Python: ``hpgen run / check / sweep`` of a model with ``inputs:``
(the SE3 quadrotor of tests/controls) with u from the scene or --u (a constant, expressions
of t, tables), bitwise equal to the API runs with the same rows; hpgen.sweep with u shared
and per member; bad u: one line, exit 2."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import hpgen
from hpgen.cli import main
from hpgen.model import load_model

QUAD = Path(__file__).resolve().parents[1] / "controls" / "quadrotor.yaml"
STEPS = 40


@pytest.fixture(scope="module")
def quad(cache_dir):
    return hpgen.compile(QUAD, cache_dir=cache_dir), load_model(QUAD)


def _run(tmp_path, cache_dir, name, *extra):
    out = tmp_path / f"{name}.npz"
    code = main(["run", QUAD, "--out", out, "--steps", STEPS, "--no-plot", "--no-progress",
                 "--cache-dir", cache_dir, *extra])
    return code, out


def test_run_with_the_scenes_u_and_with_u_tables(quad, tmp_path, cache_dir, capsys):
    integ, model = quad
    sc = model.scene
    U = sc.u.rows(sc.h, STEPS)
    ref = integ.simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, u=U)
    code, out = _run(tmp_path, cache_dir, "scene")
    assert code == 0, capsys.readouterr().err
    with np.load(out) as z:
        assert np.array_equal(z["mu"], ref.mu) and np.array_equal(z["g"], ref.g)
    np.savetxt(tmp_path / "u.csv", U, delimiter=",")
    np.savez(tmp_path / "ut.npz", u=U, t=np.arange(STEPS) * sc.h)
    for table in ("u.csv", "ut.npz"):
        code, other = _run(tmp_path, cache_dir, table.replace(".", "_"), "--u",
                           tmp_path / table)
        assert code == 0, capsys.readouterr().err
        with np.load(other) as z:
            assert np.array_equal(z["mu"], ref.mu), table
    code, const = _run(tmp_path, cache_dir, "const", "--u", "2.5", "2.4", "2.45", "m*grav/4")
    assert code == 0
    c = integ.simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, u=[2.5, 2.4, 2.45, 9.81 / 4])
    with np.load(const) as z:
        assert np.array_equal(z["mu"], c.mu)


@pytest.mark.parametrize("argv, parts", [
    (["--u", "1", "2"], ["option u", "expected 4 entries"]),
    (["--u", "1", "2", "3", "nan"], ["option u[3]", "not finite"]),
    (["--u", "1", "2", "3", "open('x')"], ["option u[3]", "not allowed"]),
    (["--u", "missing.npz"], ["option u.table", "missing.npz: no such file"]),
    (["--u-interpolation", "linear"], ["option u-interpolation"]),
])
def test_bad_u_on_the_command_line(tmp_path, cache_dir, capsys, argv, parts):
    code, out = _run(tmp_path, cache_dir, "bad", *argv)
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    for p in parts:
        assert p in err
    assert not out.exists()


def test_a_model_with_inputs_needs_u(tmp_path, cache_dir, capsys):
    path = tmp_path / "quad_no_u.yaml"
    path.write_text("\n".join(ln for ln in QUAD.read_text().splitlines()
                              if not ln.startswith("  u:")) + "\n")
    code = main(["run", path, "--out", tmp_path / "x.npz", "--no-plot", "--cache-dir",
                 cache_dir])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1
    assert "scene.u" in err and "T1, T2, T3, T4" in err and "--u" in err
    code = main(["check", path, "--steps", "10", "--cache-dir", cache_dir])
    assert code == 2 and "scene.u" in capsys.readouterr().err


def test_check_holds_u_over_the_steps_and_keeps_the_order(cache_dir):
    """The order study holds u (here a function of t) over the steps of h at every h / 2^k:
    the same piecewise-constant u(t), so the scheme's order (gauss2: 4) shows against the
    DOP853 reference restarted at the jumps; u = 0 would let the body fall."""
    from hpgen.analysis.check import run_check
    model = load_model(QUAD)
    rep = run_check(QUAD, h=0.05, steps=20, cache_dir=cache_dir, controls=model.scene.u)
    assert abs(rep["order"]["observed"][-1] - 4) < 0.25, rep["order"]
    assert rep["inputs"] == {"names": list(model.inputs), "kind": "expressions",
                             "source": "scene.u"}
    zero = run_check(QUAD, h=0.05, steps=20, cache_dir=cache_dir,
                     controls=model.scene.u.__class__("constant", model.inputs,
                                                      values=(0.0,) * 4))
    assert zero["order"]["error"][0] != rep["order"]["error"][0]


def test_sweep_cli_and_api_take_u(quad, tmp_path, cache_dir, capsys):
    integ, model = quad
    sc = model.scene
    W0 = np.array([sc.xi0, np.array(sc.xi0) * 0.5, np.array(sc.xi0) * 0.25])
    grid = tmp_path / "grid.yaml"
    grid.write_text(f"xi0: {W0.tolist()}\nsteps: {STEPS}\n")
    out = tmp_path / "s.npz"
    code = main(["sweep", QUAD, "--grid", grid, "--out", out, "--no-progress",
                 "--cache-dir", cache_dir])
    assert code == 0, capsys.readouterr().err
    U = sc.u.rows(sc.h, STEPS)
    ref = integ.simulate_batch(sc.g0, sc.h, STEPS, xi0=W0, u=U, every=sc.every)
    res = hpgen.sweep(integ, g0=sc.g0, xi0=W0, h=sc.h, steps=STEPS, u=U, progress=False)
    with np.load(out) as z:
        for i, r in enumerate(ref):
            assert np.array_equal(res["mu"][i], r.mu)
            assert np.array_equal(z["mu"][i], r.mu)
    # one u per member: (B, m) constant and (B, steps, m) rows, each member as its own run
    Um = np.array([[2.5, 2.4, 2.45, 2.5], [2.4, 2.5, 2.4, 2.5], [0.0, 0.0, 0.0, 0.0]])
    for u in (Um, np.repeat(Um[:, None, :], STEPS, axis=1)):
        res = hpgen.sweep(integ, g0=sc.g0, xi0=W0, h=sc.h, steps=STEPS, u=u, chunk_size=2,
                          progress=False)
        for i in range(3):
            one = integ.simulate(sc.g0, sc.h, STEPS, xi0=W0[i], u=Um[i])
            assert np.array_equal(res["mu"][i], one.mu)
    # B == steps: a (B, m) u is the shared (steps, m) (documented), (B, steps, m) per member
    res = hpgen.sweep(integ, g0=sc.g0, xi0=W0, h=sc.h, steps=3, u=Um, progress=False)
    assert np.array_equal(res["mu"][2], integ.simulate(sc.g0, sc.h, 3, xi0=W0[2], u=Um).mu)
    with pytest.raises(hpgen.ModelError, match="one per member"):
        hpgen.sweep(integ, g0=sc.g0, xi0=W0, h=sc.h, steps=STEPS, u=np.ones((2, 4)))
    with pytest.raises(hpgen.ModelError, match="strings"):
        hpgen.sweep(integ, g0=sc.g0, xi0=W0, h=sc.h, steps=STEPS, u=["1", "2", "3", "4"])


def test_sweep_grid_gives_u_per_member(quad, tmp_path, cache_dir, capsys):
    integ, model = quad
    sc = model.scene
    W0 = np.array([sc.xi0, np.array(sc.xi0) * 0.5])
    Um = [[2.5, 2.4, 2.45, 2.5], [0.0, 0.0, 0.0, 0.0]]
    grid = tmp_path / "grid.yaml"
    grid.write_text(f"xi0: {W0.tolist()}\nsteps: 20\nu: {Um}\n")
    out = tmp_path / "s.npz"
    assert main(["sweep", QUAD, "--grid", grid, "--out", out, "--no-progress",
                 "--cache-dir", cache_dir]) == 0, capsys.readouterr().err
    with np.load(out) as z:
        for i in range(2):
            one = integ.simulate(sc.g0, sc.h, 20, xi0=W0[i], u=Um[i], every=sc.every)
            assert np.array_equal(z["mu"][i], one.mu)
    grid.write_text(f"xi0: {W0.tolist()}\nsteps: 20\nu: [[1, 2, 3], [1, 2, 3]]\n")
    assert main(["sweep", QUAD, "--grid", grid, "--out", out, "--no-progress",
                 "--cache-dir", cache_dir]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and str(grid) in err and "u:" in err and "one per member" in err


def test_chunked_run_and_sections_take_u(quad, tmp_path, cache_dir, capsys):
    """Chunks index the rows of u by the global step (the file equals the one-call run's),
    and a scene with a section runs with the same u."""
    integ, model = quad
    code, one = _run(tmp_path, cache_dir, "one")
    code2, chunked = _run(tmp_path, cache_dir, "chunked", "--chunk", "7")
    assert code == code2 == 0, capsys.readouterr().err
    with np.load(one) as a, np.load(chunked) as b:
        assert np.array_equal(a["mu"], b["mu"]) and np.array_equal(a["work"], b["work"])
    path = tmp_path / "quad_section.yaml"
    path.write_text(QUAD.read_text().replace("  record: [g, mu, energy, work]\n",
                                             "  section: \"-R[0, 0]\"\n"))
    out = tmp_path / "sec.npz"
    assert main(["run", path, "--out", out, "--steps", 400, "--no-plot", "--cache-dir",
                 cache_dir]) == 0, capsys.readouterr().err
    sc = load_model(path).scene
    ref = hpgen.compile(path, cache_dir=cache_dir).sections(
        sc.g0, sc.h, 400, xi0=sc.xi0, u=sc.u.rows(sc.h, 400))
    with np.load(out) as z:
        assert len(ref) and np.array_equal(z["mu"], ref.mu)

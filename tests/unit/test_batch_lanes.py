"""Lane-wise ensemble kernels (hpgen.codegen.lanes, run by the C runtime's
hpgen/runtime/c/hpgen_lanes.c): simulate_batch with lanes is bitwise simulate_batch without them
(states, statuses, counters), on 1 and 2 threads, with a body count that is not a multiple
of the lane count (the remainder runs the scalar code), for full and simplified Newton,
3 and 6 unknowns, plain and composed steps; a body that fails mid-run stops with
the error of a scalar run while the other lanes of its group continue; the lane printer
gives CasADi's C bits on every op; the emitted lane code compiles without warnings; modules
where lanes do not pay get none."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from hpgen.codegen import lanes
from hpgen.runtime import NewtonOptions

ROOT = Path(__file__).resolve().parents[2]
FREE_BODY = ROOT / "examples" / "free_rigid_body.yaml"


@pytest.fixture(scope="module")
def body(compile_model):
    return compile_model(FREE_BODY)


def _momenta(B, seed=0):
    mus = np.random.default_rng(seed).normal(size=(B, 3))
    return mus / np.linalg.norm(mus, axis=1)[:, None]


def _assert_same(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert np.array_equal(x.g, y.g) and np.array_equal(x.mu, y.mu)
        assert np.array_equal(x.t, y.t)
        assert str(x.error) == str(y.error)
        assert (x.newton_iterations, x.jacobians) == (y.newton_iterations, y.jacobians)


def test_free_body_has_lanes(body):
    assert body.engine.backend.lanes == lanes.LANES


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("every", [1, 7])
def test_lanes_bitwise_equal_scalar(body, threads, every):
    B = 3 * lanes.LANES + 5                      # not a multiple of L: 5 bodies run scalar
    mus = _momenta(B) * np.linspace(0.5, 3.0, B)[:, None]
    on = body.simulate_batch(np.eye(3), 0.1, 120, mu0=mus, every=every, threads=threads)
    off = body.simulate_batch(np.eye(3), 0.1, 120, mu0=mus, every=every, threads=threads,
                              lanes=False)
    _assert_same(on, off)
    assert all(t.error is None for t in on)
    # and each body as simulate runs it on its own
    for b in (0, lanes.LANES + 1, B - 1):
        one = body.simulate(np.eye(3), 0.1, 120, mu0=mus[b], every=every)
        assert np.array_equal(one.g, on[b].g) and np.array_equal(one.mu, on[b].mu)


def test_heavy_top_stormer_verlet_g_in_the_step(compile_model):
    """A step whose residual and update read g (the heavy top's potential), 3 unknowns: lanes
    emitted, bitwise the scalar ensemble on 1 and 2 threads."""
    from scipy.spatial.transform import Rotation
    top = compile_model(ROOT / "examples" / "heavy_top.yaml", tableau="stormer-verlet",
                        tau="cay", rkmk="truncated")
    assert top.engine.backend.lanes == lanes.LANES
    B = 2 * lanes.LANES + 5
    xis = np.array([0.2, 1.0, 3.0]) + 0.3 * np.random.default_rng(3).normal(size=(B, 3))
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    for threads in (1, 2):
        on = top.simulate_batch(g0, 0.05, 150, xi0=xis, threads=threads)
        _assert_same(on, top.simulate_batch(g0, 0.05, 150, xi0=xis, threads=threads,
                                            lanes=False))
        assert all(t.error is None for t in on)


def test_one_lane_fails_the_others_continue(body):
    """Body 2 (a fast spin) needs more than maxit = 5 Newton iterations at a step: its lane
    redoes the step in scalar code, which reports NO_CONVERGENCE; the other lanes of its
    group run to the end, and everything equals the scalar ensemble."""
    B = lanes.LANES + 3
    mus = _momenta(B, seed=1)
    mus[2] *= 30.0
    opts = NewtonOptions(maxit=5)
    for threads in (1, 2):
        on = body.simulate_batch(np.eye(3), 0.1, 200, mu0=mus, newton=opts, threads=threads)
        off = body.simulate_batch(np.eye(3), 0.1, 200, mu0=mus, newton=opts,
                                  threads=threads, lanes=False)
        _assert_same(on, off)
        assert on[2].error is not None and "did not converge" in str(on[2].error)
        assert 2 < len(on[2].mu) < 201             # failed at a later step (5 today)
        assert all(t.error is None and len(t.mu) == 201 for i, t in enumerate(on) if i != 2)


def test_backend_outputs_and_statuses_equal(body):
    """The C backend's whole answer (steps done, records, every status field: code, step,
    iterations, total iterations, residual, Jacobians), also with a progress bar (thread
    slices of about 20 a thread, aligned to L)."""
    B = 2 * lanes.LANES + 3
    mus = _momenta(B, seed=2) * 2.0
    opts = body.engine.options(None)
    gs = [np.eye(3).ravel(order="F")] * B
    z0s = [body.engine.first_step.closed_start(g, m, np.zeros(3), 0.1, opts) for g, m in zip(gs, mus)]
    for threads, bar in ((1, None), (2, None), (2, SimpleNamespace(update=lambda n: None))):
        on, off = (body.engine.backend.simulate_batch(gs, list(mus), 0.1, z0s, 40, 3, opts, threads,
                                          None, bar, lanes=use) for use in (True, False))
        assert np.array_equal(on[0], off[0])
        assert np.array_equal(on[1], off[1]) and np.array_equal(on[2], off[2])
        assert on[3].dtype.names == off[3].dtype.names
        assert on[3].tolist() == off[3].tolist()


@pytest.mark.parametrize("threads", [1, 2])
def test_simplified_newton_lanes(body, monkeypatch, threads):
    """Simplified Newton runs in lanes (each lane keeps its own J^{-1} across steps, the
    scalar linear algebra lane by lane), bitwise the scalar ensemble, counters included
    (fewer Jacobians than iterations)."""
    B = lanes.LANES + 3
    mus = _momenta(B, seed=9) * np.linspace(0.5, 3.0, B)[:, None]
    opts = NewtonOptions(simplified=True)
    on, names = _batch_with_spy(body, monkeypatch, np.eye(3), 0.1, 80, mu0=mus, newton=opts,
                                every=3, threads=threads)
    assert "hpgen_advance_batch_lanes" in names
    off = body.simulate_batch(np.eye(3), 0.1, 80, mu0=mus, newton=opts, every=3,
                              threads=threads, lanes=False)
    _assert_same(on, off)
    assert all(t.error is None and t.jacobians < t.newton_iterations for t in on)


def test_simplified_one_lane_fails_the_others_continue(body):
    """Simplified Newton with maxit = 8: a faster spin's lane redoes its step in scalar code
    (from its J^{-1} before the step), which reports the failure at a later step; bitwise
    the scalar ensemble."""
    B = lanes.LANES + 3
    mus = _momenta(B, seed=1)
    mus[2] *= 5.0
    opts = NewtonOptions(maxit=8, simplified=True)
    on = body.simulate_batch(np.eye(3), 0.1, 200, mu0=mus, newton=opts)
    off = body.simulate_batch(np.eye(3), 0.1, 200, mu0=mus, newton=opts, lanes=False)
    _assert_same(on, off)
    assert on[2].error is not None and 2 < len(on[2].mu) < 201
    assert all(t.error is None for i, t in enumerate(on) if i != 2)


@pytest.fixture(scope="module")
def chain2(compile_model):
    """Two bodies coupled by a spring (Stormer-Verlet cay truncated): 6 unknowns."""
    return compile_model(ROOT / "examples" / "double_body_chain.yaml")


@pytest.mark.parametrize("newton", [None, NewtonOptions(simplified=True),
                                    NewtonOptions(simplified=True, predictor=False)])
def test_more_unknowns_than_three(chain2, monkeypatch, newton):
    """nz = 6 (the LU with partial pivoting lane by lane): lanes emitted and used, bitwise
    the scalar ensemble on 1 and 2 threads, full (the default) or simplified Newton."""
    from hpgen.model import load_model
    sc = load_model(str(ROOT / "examples" / "double_body_chain.yaml")).scene
    assert chain2.meta["nz"] == 6 and chain2.engine.backend.lanes == lanes.LANES
    B = lanes.LANES + 5
    xis = np.asarray(sc.xi0) * (1.0 + 0.2 * np.random.default_rng(11).normal(size=(B, 6)))
    for threads in (1, 2):
        on, names = _batch_with_spy(chain2, monkeypatch, sc.g0, sc.h, 80, xi0=xis, every=3,
                                    threads=threads, newton=newton)
        assert "hpgen_advance_batch_lanes" in names
        _assert_same(on, chain2.simulate_batch(sc.g0, sc.h, 80, xi0=xis, every=3,
                                               threads=threads, newton=newton, lanes=False))
        assert all(t.error is None for t in on)
    one = chain2.simulate(sc.g0, sc.h, 80, xi0=xis[B - 2], every=3, newton=newton)
    assert np.array_equal(one.mu, on[B - 2].mu) and np.array_equal(one.g, on[B - 2].g)


def test_composed_simplified_lanes(composed_body):
    """A composed step with simplified Newton (J^{-1} kept across substeps and steps, per
    lane): bitwise the scalar ensemble."""
    mus = _momenta(lanes.LANES + 1, seed=12) * 2.0
    opts = NewtonOptions(simplified=True)
    _assert_same(composed_body.simulate_batch(np.eye(3), 0.05, 60, mu0=mus, newton=opts),
                 composed_body.simulate_batch(np.eye(3), 0.05, 60, mu0=mus, newton=opts,
                                              lanes=False))


class _CallSpy:
    """A module's library that notes which of its functions were looked up."""

    def __init__(self, lib):
        self._lib, self.names = lib, set()

    def __getattr__(self, name):
        self.names.add(name)
        return getattr(self._lib, name)


def _batch_with_spy(integ, monkeypatch, *args, **kwargs):
    """(simulate_batch's trajectories, the names of the library functions it looked up)"""
    cb = integ.engine.backend
    spy = _CallSpy(cb.lib)
    monkeypatch.setattr(cb, "_lib", spy)
    try:
        out = integ.simulate_batch(*args, **kwargs)
    finally:
        monkeypatch.setattr(cb, "_lib", spy._lib)
    return out, spy.names


@pytest.fixture(scope="module")
def composed_body(compile_model):
    return compile_model(FREE_BODY, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                         compose="suzuki4")


@pytest.mark.parametrize("threads", [1, 2])
def test_composed_lanes_bitwise_equal_scalar(composed_body, monkeypatch, threads):
    """A composed step (Stormer-Verlet, suzuki4: 5 substeps, each from its own predictor
    offsets) runs in lanes (hpgen_advance_batch_lanes is called), bitwise the scalar
    ensemble and each body's own simulate; B not a multiple of L."""
    integ = composed_body
    assert integ.engine.backend.lanes == lanes.LANES
    B = 2 * lanes.LANES + 3
    mus = _momenta(B, seed=4) * np.linspace(0.5, 2.5, B)[:, None]
    on, names = _batch_with_spy(integ, monkeypatch, np.eye(3), 0.05, 90, mu0=mus, every=4,
                                threads=threads)
    assert "hpgen_advance_batch_lanes" in names
    off, names = _batch_with_spy(integ, monkeypatch, np.eye(3), 0.05, 90, mu0=mus, every=4,
                                 threads=threads, lanes=False)
    assert "hpgen_advance_batch_lanes" not in names
    _assert_same(on, off)
    assert all(t.error is None for t in on)
    assert on[0].newton_iterations > 0
    for b in (0, lanes.LANES + 2, B - 1):
        one = integ.simulate(np.eye(3), 0.05, 90, mu0=mus[b], every=4)
        assert np.array_equal(one.g, on[b].g) and np.array_equal(one.mu, on[b].mu)
        assert one.newton_iterations == on[b].newton_iterations


def test_composed_lanes_without_predictor(composed_body):
    """Without the predictor each substep starts from the substep before's solution."""
    mus = _momenta(lanes.LANES, seed=5) * 2.0
    opts = NewtonOptions(predictor=False)
    _assert_same(composed_body.simulate_batch(np.eye(3), 0.05, 60, mu0=mus, newton=opts),
                 composed_body.simulate_batch(np.eye(3), 0.05, 60, mu0=mus, newton=opts,
                                              lanes=False))


def test_composed_one_lane_fails_the_others_continue(composed_body):
    """Body 1 (a faster spin, h = 0.2) needs more than maxit = 4 iterations in some substep
    of its third step: its lane redoes the composed step in scalar code (from the state
    before the step), which reports NO_CONVERGENCE; the other lanes run to the end;
    everything equals the scalar ensemble."""
    B = lanes.LANES + 1
    mus = _momenta(B, seed=6) * 0.5
    mus[1] = [-4.909257111181791, -3.5734690654455825, -1.4241795057337374]
    opts = NewtonOptions(maxit=4)
    for threads in (1, 2):
        on = composed_body.simulate_batch(np.eye(3), 0.2, 60, mu0=mus, newton=opts,
                                          threads=threads)
        off = composed_body.simulate_batch(np.eye(3), 0.2, 60, mu0=mus, newton=opts,
                                           threads=threads, lanes=False)
        _assert_same(on, off)
        assert on[1].error is not None and "did not converge" in str(on[1].error)
        assert len(on[1].mu) == 3                 # steps 0 and 1 done, step 2 failed
        assert all(t.error is None and len(t.mu) == 61 for i, t in enumerate(on) if i != 1)


def test_composed_heavy_top_lanes(compile_model):
    """A composed step whose residual and update read g (the heavy top): bitwise the
    scalar ensemble."""
    from scipy.spatial.transform import Rotation
    top = compile_model(ROOT / "examples" / "heavy_top.yaml", tableau="stormer-verlet",
                        tau="cay", rkmk="truncated", compose="yoshida4")
    B = lanes.LANES + 2
    xis = np.array([0.2, 1.0, 3.0]) + 0.3 * np.random.default_rng(7).normal(size=(B, 3))
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    on = top.simulate_batch(g0, 0.05, 80, xi0=xis, every=3)
    _assert_same(on, top.simulate_batch(g0, 0.05, 80, xi0=xis, every=3, lanes=False))
    assert all(t.error is None for t in on)


def test_explicit_composed_lanes(compile_model):
    """The explicit lanes' composed path (hpgen_run_cstep's substeps of an explicit step;
    the API refuses to compose a splitting scheme, so the runs are composed here directly):
    bitwise the scalar runs."""
    split = compile_model(FREE_BODY, tableau="split2")
    cb = split.engine.backend
    assert cb.lanes == lanes.LANES
    mus = _momenta(lanes.LANES + 2, seed=8) * 2.0
    cb.compose = (0.6, -0.2, 0.6)
    try:
        on = split.simulate_batch(np.eye(3), 0.05, 50, mu0=mus, every=5)
        off = split.simulate_batch(np.eye(3), 0.05, 50, mu0=mus, every=5, lanes=False)
    finally:
        cb.compose = ()
    _assert_same(on, off)
    plain = split.simulate_batch(np.eye(3), 0.05, 50, mu0=mus, every=5)
    assert not np.array_equal(plain[0].mu, on[0].mu)       # the composition took effect


def _lane_region(source: str) -> tuple[int, int]:
    """The lines of kernels.c's lane kernels (from the #define HPGEN_L to the end of the
    region)."""
    lines = source.splitlines()
    start = next(i for i, s in enumerate(lines) if s.startswith("#define HPGEN_L ")) + 1
    end = next(i for i, s in enumerate(lines) if s == "HPGEN_LANES_END") + 1
    return start, end


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")
def test_lane_code_compiles_without_warnings(body, tmp_path):
    """-Wall -Wextra -Werror: no diagnostic points into the lane kernels of kernels.c or into
    the runtime (hpgen/runtime/c, hpgen_lanes.c included; CasADi's part of kernels.c is
    checked by its own tests)."""
    from hpgen.runtime.build import RUNTIME_DIR, include_flags
    source = (Path(body.engine.backend.library).parent / "kernels.c").read_text()
    start, end = _lane_region(source)
    src = tmp_path / "kernels.c"
    src.write_text(source)
    out = subprocess.run(["cc", "-std=c99", "-O3", "-Wall", "-Wextra", "-Werror", "-fPIC",
                          *include_flags(), "-c", str(src), "-o", str(tmp_path / "k.o")],
                         capture_output=True, text=True)
    lines = [int(m.group(1)) for m in
             re.finditer(r"kernels\.c:(\d+):\d+: (?:warning|error)", out.stderr)]
    assert not [n for n in lines if start <= n <= end], out.stderr
    runtime = re.findall(rf"{re.escape(str(RUNTIME_DIR))}/\S+: (?:warning|error)", out.stderr)
    assert not runtime, out.stderr
    assert "hpgen_lanes.c" not in out.stderr and "hpgen_runtime" not in out.stderr, out.stderr


def test_no_lanes_where_they_do_not_pay():
    """Open models and steps with more than LANES_MAX_NZ unknowns get no lane code."""
    assert lanes.lanes_context(SimpleNamespace(open_spec=None, nz=lanes.LANES_MAX_NZ + 1),
                               100) is None
    assert lanes.lanes_context(SimpleNamespace(open_spec=object(), nz=3), 100) is None
    assert lanes.lanes_context(SimpleNamespace(open_spec=None, nz=3),
                               lanes.LANES_MAX_INSTRUCTIONS + 1) is None


def test_lane_literals_read_back():
    for v in (0.1, 2.0, -1e-300, 6.6666666666666663e-01, 1e22):
        assert float(lanes.c_double(v)) == v
    assert lanes.c_double(2.0) == "2.0" and lanes.c_double(1e22) == "1e+22"


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler")
def test_lane_printer_bitwise_casadi_c_on_every_op(tmp_path):
    """Every scalar op the printers know (test_codegen's all-ops function): the lane kernel,
    compiled as the lanes section is (-O3, no-trapping-math pragma), gives on each lane the
    bits of CasADi's own C code for the same function, compiled in the same file."""
    import ctypes

    import casadi as ca

    from hpgen.derive.step import Kernel
    from tests.unit.test_codegen import _all_ops_function

    f = _all_ops_function()
    L, n = lanes.LANES, f.numel_out(0)
    lane = lanes.lane_kernel_source(Kernel("allops", f, ("x",), ("y",)))
    assert lane is not None
    cg = ca.CodeGenerator("allops_ref", {"with_header": False, "casadi_real": "double",
                                         "casadi_int": "long long int"})
    cg.add(f)
    src = tmp_path / "allops.c"
    src.write_text(
        "#include <math.h>\n#include <string.h>\n" + cg.dump() + "\n"
        "#pragma GCC optimize(\"no-trapping-math\")\n" + lane + f"""
void run(const double* xs, double* lane_out, double* ref_out) {{
    double in[2 * {L}];
    long long iw[{max(1, f.sz_iw())}];
    double w[{f.sz_w() + 1}];
    int l;
    for (l = 0; l < {L}; ++l) {{
        const double* arg[1];
        double* res[1];
        in[l] = xs[2 * l]; in[{L} + l] = xs[2 * l + 1];
        arg[0] = xs + 2 * l; res[0] = ref_out + {n} * l;
        allops(arg, res, iw, w, 0);
    }}
    hpgen_lane_allops(in, lane_out);
}}
""")
    lib = tmp_path / "allops.so"
    subprocess.run(["cc", "-std=c99", "-O3", "-fPIC", "-shared", str(src), "-o", str(lib),
                    "-lm"], check=True, capture_output=True)
    run = ctypes.CDLL(str(lib)).run
    points = [(0.5, 0.25), (-0.5, 2.0), (0.0, 0.0), (-0.0, -3.0), (2.0, -0.0), (1.0, 1.0),
              (-1.0, 0.5), (np.inf, 1.0), (-np.inf, 2.0), (np.nan, 1.0), (3.7, -2.2),
              (1e300, 1e-300)]
    points += [(0.3, 0.7)] * (-len(points) % L)
    for i in range(0, len(points), L):
        xs = np.array(points[i:i + L], dtype=np.float64).ravel()
        got, ref = np.zeros(n * L), np.zeros(n * L)
        run(xs.ctypes.data_as(ctypes.c_void_p), got.ctypes.data_as(ctypes.c_void_p),
            ref.ctypes.data_as(ctypes.c_void_p))
        got = got.reshape(n, L).T                  # SoA -> (lane, entry)
        ref = ref.reshape(L, n)
        same = (got.view(np.int64) == ref.view(np.int64)) | (np.isnan(got) & np.isnan(ref))
        assert same.all(), (points[i:i + L], np.argwhere(~same))

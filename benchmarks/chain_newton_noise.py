"""The round-off noise of a many-body step's Newton correction against N: cond(J) and |dz*|,
the correction Newton computes at a converged solution z* (dz* = J^{-1} F(z*): F's round-off
mapped through J^{-1}), on a ball-joint chain (SV / cay / truncated, C backend, sparse J).

    PYTHONPATH=. python benchmarks/chain_newton_noise.py [--model examples/pendulum_chain.yaml]
                                                        [--n 8 16 32 64] [--steps 120]

--model: examples/pendulum_chain.yaml (frames at the pin: link i's inertia about its frame
m (i + 1/2)^2 |b|^2) or a chain with every frame at its link's centre (x[i] the centre's
offset from the straight chain hanging down, g = identity; e.g. examples/capsule_chain.yaml);
the frames are told apart by the model's name containing "capsule". Three starts per N: the
example's scene (every link spinning with w = (3, 1, 0.5), the straight chain rigid), a slow
one (w / 10), random joint velocities (hpgen.bench.multibody.chain.initial_joint_state).
Steps from the previous solution (no predictor), full Newton; every 30 steps J (dense, numpy)
at the solution: median cond(J) (2-norm), |z*|, |dz*| and |dz*| / (1 + |z*|) (inf-norms), and
the a priori bound eps |J^{-1}| (|J| |z*|) (F's constant terms left out, so it can fall short).
"""
from __future__ import annotations

import argparse

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime.newton import NewtonOptions


def starts(n: int, centres: bool) -> dict:
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    state = chain.from_joint(spec, qpos, qvel)
    if not centres:
        g0, xi0 = hpgen_chain.to_hpgen(spec, state)
        return {"scene": (np.eye(4 * n), np.tile([3.0, 1.0, 0.5, 0, 0, 0], n)),
                "slow": (np.eye(4 * n), np.tile([0.3, 0.1, 0.05, 0, 0, 0], n)),
                "random": (g0, xi0)}
    c = (np.arange(n)[:, None] + 0.5) * np.array([0.0, 0.0, -spec.length])

    def rigid(w):
        w = np.asarray(w, dtype=float)
        return np.concatenate([np.concatenate([w, np.cross(w, c[i])]) for i in range(n)])
    g0, xi0 = np.eye(4 * n), np.zeros(6 * n)
    for i in range(n):
        g0[4 * i:4 * i + 3, 4 * i:4 * i + 3] = state.R[i]
        g0[4 * i:4 * i + 3, 4 * i + 3] = state.x[i] - c[i]
        xi0[6 * i:6 * i + 3] = state.omega[i]
        xi0[6 * i + 3:6 * i + 6] = state.R[i].T @ state.v[i]
    return {"scene": (np.eye(4 * n), rigid([3.0, 1.0, 0.5])),
            "slow": (np.eye(4 * n), rigid([0.3, 0.1, 0.05])), "random": (g0, xi0)}


def measure(integ, g0, xi0, steps: int) -> dict:
    eng = integ.engine
    nz, hv = eng.nz, np.array([1e-3])
    opts = eng.options(NewtonOptions(simplified=False), full=True)
    gf = g0.ravel(order="F")
    p = eng.kernel("legendre", gf, xi0)[0]
    z = eng.kernel("guess", xi0, gf, p, hv)[0]
    rows = []
    for k in range(steps):
        code, g1, p1, z, _, _ = eng.backend.step(gf, p, hv, z, opts)
        if code != 0:
            raise SystemExit(f"step {k}: status {code}")
        if k % 30 == 29:
            F, J = eng.kernel("residual_jacobian", z, gf, p, hv)
            J = np.asarray(J).reshape(nz, nz, order="F")
            dz = np.linalg.solve(J, np.asarray(F).ravel())
            bound = np.finfo(float).eps * np.abs(np.linalg.solve(J, np.abs(J) @ np.abs(z)))
            rows.append((np.linalg.cond(J), np.abs(z).max(), np.abs(dz).max(), bound.max()))
        gf, p = g1, p1
    cond, zn, dn, bound = np.median(np.array(rows), axis=0)
    return {"cond": cond, "z": zn, "dz": dn, "rel": dn / (1 + zn), "bound": bound}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--model", default=str(hpgen_chain.MODEL))
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--steps", type=int, default=120)
    a = ap.parse_args()
    centres = "capsule" in a.model
    print(f"hpgen from {hpgen.__file__}; {a.model} (frames at the "
          f"{'centres' if centres else 'pin'})")
    print("| N | start | cond(J) | abs z* | abs dz* | dz* / (1 + z*) | eps bound |")
    print("|---|---|---|---|---|---|---|")
    for n in a.n:
        integ = hpgen.compile(a.model, parameters={"N": n})
        for name, (g0, xi0) in starts(n, centres).items():
            r = measure(integ, g0, xi0, a.steps)
            print(f"| {n} | {name} | {r['cond']:.2e} | {r['z']:.2e} | {r['dz']:.2e} | "
                  f"{r['rel']:.1e} | {r['bound']:.1e} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

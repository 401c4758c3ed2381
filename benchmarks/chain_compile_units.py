"""The step of the pendulum chain built as translation units (hpgen.codegen.cparts) against
the same kernels.c built as one unit: us/step of each, interleaved in one process.

    PYTHONPATH=. python benchmarks/chain_compile_units.py --n 8 64 --tableau stormer-verlet
    PYTHONPATH=. python benchmarks/chain_compile_units.py --n 8 --tableau gauss2

The one-unit library is compiled from the split kernels.c without -DHPGEN_PART (the macros
then make it one translation unit, every function static); both load from copies of the
same module directory, so only the build differs. Every N starts from the chain's joint-space
initial state (hpgen.bench.multibody.chain, h = 1e-3); us/step is the median over ``rounds``
alternating runs of ``steps`` steps. Prints a Markdown row per N with the ratio
split / one unit (1.00: the same speed).
"""
from __future__ import annotations

import argparse
import shutil
import statistics
import tempfile
import time
from pathlib import Path

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime import build

MODEL = hpgen_chain.MODEL


def one_unit_copy(module_dir: Path, dest: Path) -> Path:
    """A copy of the module whose library is kernels.c compiled as one translation unit."""
    shutil.copytree(module_dir, dest, ignore=shutil.ignore_patterns("_kernels_*", "MANIFEST*"))
    text = (dest / "kernels.c").read_text()
    (dest / "kernels.c").write_text(text.replace("\n#define HPGEN_PARTS ",
                                                 "\n#define HPGEN_ONE_UNIT_OF_PARTS "))
    if build.translation_units((dest / "kernels.c").read_bytes()) != 1:
        raise SystemExit("could not make a one-unit copy")
    return dest


def us_per_step(integ, g0, xi0, steps: int) -> float:
    t = time.perf_counter()
    integ.simulate(g0, 1e-3, steps, xi0=xi0, every=steps)
    return (time.perf_counter() - t) / steps * 1e6


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 64])
    ap.add_argument("--tableau", default="stormer-verlet")
    ap.add_argument("--steps", type=int, default=500)
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--cache-dir", default=None)
    args = ap.parse_args()
    print(f"tableau {args.tableau}")
    print("| N | split us/step | one unit us/step | split / one unit |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="hpgen-units-") as tmp:
        for n in args.n:
            c = hpgen.build(MODEL, parameters={"N": n}, tableau=args.tableau,
                            cache_dir=args.cache_dir, backend="c")
            if build.translation_units((c.module_dir / "kernels.c").read_bytes()) == 1:
                print(f"| {n} | (not split) | | |")
                continue
            one = one_unit_copy(c.module_dir, Path(tmp) / f"one{n}")
            integs = [c.load(), hpgen.load(one, backend="c")]
            spec = chain.ChainSpec(n)
            qpos, qvel = chain.initial_joint_state(spec)
            g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
            times: list[list[float]] = [[], []]
            for integ in integs:
                us_per_step(integ, g0, xi0, 20)                         # warm up
            for _ in range(args.rounds):
                for k, integ in enumerate(integs):
                    times[k].append(us_per_step(integ, g0, xi0, args.steps))
            a, b = (statistics.median(t) for t in times)
            print(f"| {n} | {a:.1f} | {b:.1f} | {a / b:.3f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

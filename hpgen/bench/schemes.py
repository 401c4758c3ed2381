"""hpgen's own schemes in the benchmark: compile once per (tableau, tau, rkmk), run per h.

Each scheme is ``hpgen.build(path, tableau, tau, rkmk, backend="c", cache_dir).load()`` (its
wall time is the point's setup_s; the CompiledModule says whether the cache served it) and each point one C call of
``Integrator.simulate(g0, xi0 or mu0 (as the scene gives it), h, steps, every=steps)``,
the whole of it timed, including simulate's Python prologue (checks, Legendre transform,
initial guess), whose cost alone (steps = 0) is given in the notes. The sampled run records
every max(1, steps // samples) steps. The state compared is (g_N, p_N), p_N the node
momentum.
"""
from __future__ import annotations

import time

from ..errors import ModelError
from .measure import FAILURES, Point, fixed_note, measure, steps_for

#: the default grid: (tableau, tau, rkmk)
DEFAULT_SCHEMES = (("stormer-verlet", "cay", "truncated"), ("gauss2", "exp", "exact"),
                   ("gauss2", "cay", "exact"), ("gauss3", "cay", "exact"))
#: the splitting schemes the default grid adds for a model with their structure
DEFAULT_SPLITTINGS = ("split4-suzuki", "split6-kahan-li", "split8-kahan-li",
                      "split4-blanes-moan-fasso", "split6-blanes-moan-fasso")


def validate_schemes(schemes):
    """ModelError (one line) for an unknown tableau, tau or rkmk, before anything is built."""
    from ..schemes import RKMK_CHOICES, TAU_CHOICES
    from ..splitting import SPLITTING_NAMES
    from ..tableaus import TABLEAU_NAMES
    if not schemes:
        raise ModelError("expected at least one scheme", field="option tableau")
    for tab, tau, rkmk in schemes:
        if tab not in TABLEAU_NAMES + SPLITTING_NAMES:
            raise ModelError(f"expected one of {', '.join(TABLEAU_NAMES + SPLITTING_NAMES)}, "
                             f"got {tab!r}", field="option tableau")
        if tau not in TAU_CHOICES:
            raise ModelError(f"expected one of {', '.join(TAU_CHOICES)}, got {tau!r}",
                             field="option tau")
        if rkmk not in RKMK_CHOICES:
            raise ModelError(f"expected one of {', '.join(RKMK_CHOICES)}, got {rkmk!r}",
                             field="option rkmk")
    return [tuple(s) for s in schemes]


def scheme_name(tab, tau, rkmk):
    """The scheme's label; a splitting scheme's step uses no chart map nor RKMK constraint."""
    from ..splitting import is_splitting
    return f"hpgen {tab}" if is_splitting(tab) else f"hpgen {tab}/{tau}/{rkmk}"


def hpgen_points(pb, y_ref, schemes, hs, timing, samples, cache_dir=None, log=None):
    import hpgen
    out = []
    kw0 = {"g0": pb.g0}
    kw0.update({"xi0": pb.xi0} if pb.xi0 is not None else {"mu0": pb.mu0})
    if pb.u is not None:              # the inputs, held over every step (t0 = 0)
        kw0["u"] = pb.u
    for tab, tau, rkmk in schemes:
        name = scheme_name(tab, tau, rkmk)
        t0 = time.perf_counter()
        compiled = hpgen.build(pb.path, tableau=tab, tau=tau, rkmk=rkmk, backend="c",
                               cache_dir=cache_dir)
        integ = compiled.load()
        setup = time.perf_counter() - t0
        how = ("cache hit" if compiled.cached and not compiled.built else
               "cached sources, C build" if compiled.cached else "cold: generate + C build")
        try:      # simulate's fixed cost (checks, Legendre transform, guess): steps = 0
            pro = timing.median(lambda: integ.simulate(h=hs[0], steps=0, **kw0))[0]
        except FAILURES:
            pro = float("nan")
        if log:
            log(f"  {name}: compiled in {setup:.2f} s ({how}; {integ.nz} unknowns)")
        for h in hs:
            steps, hu = steps_for(pb.T, h)
            every = max(1, steps // samples)
            p = Point(name + " (C)", name, "hpgen", "h", hu, setup_s=setup,
                      setup_note=f"hpgen.compile, {how}, in this process")
            p.notes += fixed_note(h, hu)

            def sampled(hu=hu, steps=steps, every=every):
                tr = integ.simulate(h=hu, steps=steps, every=every, **kw0)
                return tr.t, pb.pack(tr.g, tr.mu)

            def timed(hu=hu, steps=steps):
                tr = integ.simulate(h=hu, steps=steps, every=steps, **kw0)
                return pb.pack(tr.g[-1], tr.mu[-1]), {
                    "steps": steps, "notes": [
                        f"Newton it/step {tr.newton_iterations / steps:.2f}",
                        f"wrong-root guard re-solves {tr.guarded}",
                        f"simulate prologue (steps = 0) {pro * 1e6:.0f} us"]}
            out.append(measure(pb, y_ref, p, timing, timed, sampled))
    return out


def ladder(h0, k=4):
    """h0 * 2^-j, j = 0..k."""
    return [h0 * 2.0 ** -j for j in range(k + 1)]


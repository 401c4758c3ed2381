"""The text and JSON forms of an ``hpgen check`` report (hpgen.analysis.check.run_check's
dict): ``format_report`` for the terminal, ``write_json`` for ``--json``.
"""
from __future__ import annotations

import json
from pathlib import Path

from ..errors import ModelError
from ..files import write_file
from .check import GROUP_TOL
from .check_order import FLOOR, ORDER_TOL, REFINE_MAX_STEPS


def _verdict(ok):
    return "n/a" if ok is None else ("PASS" if ok else "FAIL")


def _regime(o) -> str:
    """Where the expected order shows: 'from h = X', or why it was not seen."""
    if o["asymptotic_h"] is not None:
        return f"from h = {o['asymptotic_h']:.3g}"
    return "floor" if o["status"] == "floor" else f"not by h = {o['refined']['h'][-1]:.3g}"


def _regime_note(o) -> str:
    ref = o["refined"]
    extra = len(ref["h"]) - len(o["h"])
    slopes = " ".join("-" if v is None else f"{v:.2f}" for v in ref["observed"])
    if o["status"] == "asymptotic" and not extra:
        return f"the observed order agrees with {o['expected']} (within {ORDER_TOL:g})"
    if o["status"] == "floor":
        return (f"the errors reach the reference floor ({FLOOR:g}) before two slopes agree "
                f"with {o['expected']}: {slopes}")
    if o["status"] == "asymptotic":
        return (f"pre-asymptotic at h = {o['h'][0]:g}: halving h down to {ref['h'][-1]:.3g}, "
                f"the slopes are {slopes}")
    return (f"the slopes {slopes} down to h = {ref['h'][-1]:.3g} (budget "
            f"{REFINE_MAX_STEPS} steps per run) do not agree with {o['expected']}")


def format_report(r: dict) -> str:
    """The report as a plain-text table."""
    it = r["integrator"]
    name = (f"{it['tableau']}/{it['tau']}/{it['rkmk']} ({it['backend']})"
            + (f" composed {it['compose']}" if it.get("compose") else "")
            if r["scheme"] == "hpgen" else "RKMK-RK4 (exp, explicit, not variational)")
    o, e, mo, s, c = r["order"], r["energy"], r["momentum"], r["symplectic"], r["checks"]
    fmt = " ".join
    rows = [
        ("observed order", fmt("-" if v is None else f"{v:.2f}" for v in o["observed"]),
         f"expected {o['expected']} ({o['why']}); T = {o['horizon']:g}; errors "
         + fmt(f"{v:.2e}" for v in o["error"])
         + f" at h = {o['h'][0]:g}, /2, /4" + (" (near the reference floor)" if o["floor"]
                                               else "")),
        ("asymptotic regime", _regime(o), _regime_note(o)),
        (("energy-work max |E - W - E0|" if e.get("balance") else "energy max |E - E0|"),
         f"{e['max_error']:.3e}", f"relative {e['relative_max_error']:.2e}"
         + ("; W: the forces' work (node rule, docs/numerics.md sec. 13)"
            if e.get("balance") else "")),
        ("energy drift slope", f"{e['drift_slope']:.3e}", "per unit time (linear fit)"),
        (("momentum - impulse" if mo.get("balance") else "spatial momentum change"),
         fmt(f"{v:.1e}" for v in mo["max_change"]),
         ("max |m_k - m_0 - int Ad*_{g^-1} f dt| per component (forced: to the scheme's "
          "order, informative)" if mo.get("balance") else
          f"{_verdict(c['momentum'])} (max per component"
          + ("" if mo["left_invariant"] else "; l depends on g") + ")"
          + ("; forced" if r["energy"].get("balance") else ""))),
        ("group defect max", f"{r['group_defect']['max']:.2e}",
         f"{_verdict(c['group'])} (<= {GROUP_TOL:g})"),
        ("symplecticity defect", "n/a", "forced: the flow is not symplectic (zero forces "
         "give the defect)") if s["defect"] is None else
        ("symplecticity defect", f"{s['defect']:.2e}",
         f"{_verdict(c['symplectic'])}: relative {s['relative']:.2e} "
         f"{'<=' if c['symplectic'] else '>'} {s['tolerance']:.1e} "
         f"at {len(s['states'])} states"
         + (" (on the constraint manifold's tangent space)" if s.get("on_manifold") else "")),
    ]
    y = r.get("symmetry")
    if y is not None:
        rows.append(("base step symmetry", f"{y['defect']:.1e}",
                     f"{_verdict(c['symmetric'])}: max |S(-h) S(h) x - x| / (1 + |p|) "
                     f"<= {y['tolerance']:g} (the composition's order needs it)"))
    k = r.get("constraints")
    if k is not None:
        rows.append(("constraint residual", f"{k['position']:.1e} {k['velocity']:.1e}",
                     f"{_verdict(c['constraints'])} (max |phi|, max |Phi xi| over the run, "
                     f"{k['count']} rows; <= {k['tolerance']:g})"))
    w0 = max(len(a) for a, _, _ in rows)
    w1 = max(len(b) for _, b, _ in rows)
    head = (f"hpgen check: {r['model']} ({r['group']}), {name}, h = {r['h']:g}, "
            f"{r['steps']} steps (T = {r['duration']:g})")
    lines = [head, f"  {'quantity':{w0}s}  {'value':{w1}s}  note"]
    lines += [f"  {a:{w0}s}  {b:{w1}s}  {n}" for a, b, n in rows]
    if r.get("inputs"):
        u = r["inputs"]
        lines.append(f"  inputs {', '.join(u['names'])}: {u['kind']} from {u['source']}, held "
                     "over each step of h")
    lines.append(f"  result: {'PASS' if r['passed'] else 'FAIL'} ({r['seconds']:.1f} s)")
    return "\n".join(lines)


def write_json(report: dict, path) -> Path:
    """Write the report as JSON atomically (temp file + os.replace)."""
    path = Path(path)
    try:
        write_file(path, json.dumps(report, indent=2) + "\n")
    except OSError as e:
        raise ModelError(f"cannot write the JSON report ({e.strerror})", file=str(path)) from None
    return path

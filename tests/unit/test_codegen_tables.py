"""The integer tables of kernels.c: hpgen.codegen.emit.wrapped_ints gives the text of jinja2's
``join(", ") | wordwrap(90)`` (what the template printed before), and the static LU's heap
order is Markowitz's order of the scan it replaced."""
from __future__ import annotations

import random

import jinja2

from hpgen.codegen.emit import wrapped_ints
from hpgen.codegen.static_lu import static_lu


def test_wrapped_ints_is_jinja_wordwrap():
    template = jinja2.Environment().from_string('{{ v | join(", ") | wordwrap(90) }}')
    rng = random.Random(7)
    for n in (0, 1, 2, 5, 17, 31, 200, 2000):
        for _ in range(20):
            values = [rng.randint(-9, 10 ** rng.randint(0, 12)) for _ in range(n)]
            assert wrapped_ints(values) == template.render(v=values)


def _scan_order(n, colind, row):
    """The pivot order of the plain scan: at each step the ready unknown of least
    ((|row| - 1)(|col| - 1), index) on the structure with fill; None when none is ready."""
    rows = [set() for _ in range(n)]
    cols = [set() for _ in range(n)]
    for c in range(n):
        for r in row[colind[c]:colind[c + 1]]:
            rows[r].add(c)
            cols[c].add(r)
    waits = {k: (rows[k] | cols[k]) - {k} for k in range(n) if k not in rows[k]}
    alive, perm = set(range(n)), []
    while alive:
        ready = [k for k in alive if k in rows[k] and not (waits.get(k, set()) & alive)]
        if not ready:
            return None
        k = min(ready, key=lambda v: ((len(rows[v]) - 1) * (len(cols[v]) - 1), v))
        lower, upper = cols[k] - {k}, rows[k] - {k}
        perm.append(k)
        for i in lower:
            rows[i] |= upper
            rows[i].discard(k)
        for j in upper:
            cols[j] |= lower
            cols[j].discard(k)
        alive.discard(k)
    return tuple(perm)


def test_static_lu_order_is_the_scan_order():
    rng = random.Random(11)
    found = missing = 0
    for _ in range(1500):
        n = rng.randint(1, 14)
        p = rng.random() * 0.6
        entries = {(r, c) for r in range(n) for c in range(n) if rng.random() < p}
        entries |= {(k, k) for k in range(n) if rng.random() < 0.75}
        if rng.random() < 0.5:
            entries |= {(c, r) for r, c in entries}
        colind, row = [0], []
        for c in range(n):
            row += sorted(r for r, cc in entries if cc == c)
            colind.append(len(row))
        lu, want = static_lu(n, colind, row), _scan_order(n, colind, row)
        assert (lu.perm if lu is not None else None) == want
        found += lu is not None
        missing += lu is None
    assert found > 100 and missing > 100        # both outcomes exercised

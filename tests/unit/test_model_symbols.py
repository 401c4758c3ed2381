"""hpgen.model.values makes a family's many real symbols without sympy's per-symbol
canonicalisation: each must be sympy's Symbol(name, real=True) in every respect that
expressions use (equality, hash, assumptions, arithmetic, pickling)."""
from __future__ import annotations

import pickle

import sympy as sp

from hpgen.model.values import _real_symbols, _symbols


def test_real_symbols_are_sympys():
    names = [f"q_{i}_{j}" for i in range(5) for j in range(7)]
    made = _real_symbols(names)
    for name, s in zip(names, made):
        ref = sp.Symbol(name, real=True)
        assert s == ref and hash(s) == hash(ref) and s.name == name
        assert s.assumptions0 == ref.assumptions0
        assert s.is_real and s.is_positive is None and s != sp.Symbol(name)
        assert pickle.loads(pickle.dumps(s)) == ref
        assert sp.diff(s ** 2 + ref, ref) == 2 * ref + 1
        assert (s - ref) == 0


def test_family_g_symbols():
    g = _symbols("g", 8, 8)
    assert g.shape == (8, 8) and not g.flags.writeable
    assert g[3, 5] == sp.Symbol("g_3_5", real=True)
    assert len({s for s in g.flat}) == 64
